#pragma once
// The request keys that validation messages quote ("'width', 'height': ...") and the option each
// is in the command line's terms: what inFlagTerms (commands/Common.cpp) writes instead. Checked
// by tests/app/test_cli.cpp against the options the commands accept and the keys the JSON
// requests accept, so the table cannot drift from either.

#include <utility>

namespace sdfwb::app {

// The keys whose option is not "--" + the key with '-' for '_', as messages quote them.
inline constexpr std::pair<const char*, const char*> kRenamedKeys[] = {
    {"'width', 'height'", "--size"},
    {"'x', 'y'", "--pixel"},
    {"'shard_index', 'shard_count'", "--shard"},
    {"'bounds_min', 'bounds_max'", "--bounds"},
    {"'channels'", "--channel"},
    {"'params_end'", "--param-end"},
    {"'params'", "--param"},
    {"'over_relaxation'", "--relaxation"},
    {"'near_truncation'", "--near-truncate"},
    {"'items'", "--item"},
    {"'n'", "-n"},
    {"'sdf': ", "--sdf: "}, // only as the message's subject: 'sdf' is also the usual entry point's name
};

// The rest of the keys that messages name: the option is "--" + the key with '-' for '_'.
inline constexpr const char* kSameNamedKeys[] = {
    "entry",
    "randomize",
    "sweep",
    "output",
    "time",
    "fov",
    "max_steps",
    "step_factor",
    "cone_tile",
    "contour_spacing",
    "plane",
    "camera",
    "target",
    "background_image",
    "background",
    "seconds",
    "fps",
    "pattern",
    "gradient_step",
    "surface_tolerance",
    "near_widths",
    "samples",
    "truncation_reach",
    "resolution",
    "refine",
    "repeats",
    "world_size",
    "rank",
    "item_timeout",
    "status",
    "lipschitz",
    "error_samples",
    "mesh",
    "points",
    "tau",
    "occupancy_resolution",
    "edge_radius",
    "edge_angle",
    "sign",
    "normalize",
    "format",
    "chunk",
};

} // namespace sdfwb::app
