#pragma once
// The job kinds, one row each: a request type's name (its JSON "kind" and its CLI command),
// whether it needs a GL context, the name it had before (still read, never written) and the
// Python function that runs it (every kind also runs through sdfwb.run).
// kindName, needsGl, the JSON dispatch and every list of kinds in a message derive from this
// table; the CLI's commands are checked against it (test_cli). A request type added to the
// Request variant without a row here does not compile.

#include <values/Requests.h>

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace sdfwb::values {

struct JobKind {
    std::string_view name; // a string literal: name.data() is null-terminated
    bool needsGl = true;
    std::string_view formerName = {};
    std::string_view python = {}; // empty: through sdfwb.run only (the Python tests check the names)
};

template <class RequestType> struct JobKindOf; // the rows: no row, no kind

template <> struct JobKindOf<RenderRequest> { static constexpr JobKind row{"render", true}; };
template <> struct JobKindOf<AnimateRequest> { static constexpr JobKind row{"animate", true}; };
template <> struct JobKindOf<SampleRequest> { static constexpr JobKind row{"sample", true, {}, "sample"}; };
template <> struct JobKindOf<AuditRequest> { static constexpr JobKind row{"audit", true, {}, "audit"}; };
template <> struct JobKindOf<MergeRequest> { static constexpr JobKind row{"merge", false}; };
template <> struct JobKindOf<ListRequest> { static constexpr JobKind row{"list", false, {}, "list_sdfs"}; };
template <> struct JobKindOf<BenchRequest> { static constexpr JobKind row{"bench", true}; };
template <> struct JobKindOf<ParamsRequest> { static constexpr JobKind row{"params", false, {}, "params"}; };
template <> struct JobKindOf<MeshRequest> { static constexpr JobKind row{"mesh", true, {}, "mesh"}; };
template <> struct JobKindOf<EvalRequest> { static constexpr JobKind row{"grade", true, "eval", "evaluate_mesh"}; };
template <> struct JobKindOf<RunRequest> { static constexpr JobKind row{"run", false}; };
template <> struct JobKindOf<ProbeRequest> { static constexpr JobKind row{"probe", true}; };

namespace detail {
template <std::size_t... I> constexpr auto jobKindRows(std::index_sequence<I...>) {
    return std::array<JobKind, sizeof...(I)>{JobKindOf<std::variant_alternative_t<I, Request>>::row...};
}
} // namespace detail

// Every kind, in the Request variant's order.
inline constexpr auto kJobKinds = detail::jobKindRows(std::make_index_sequence<std::variant_size_v<Request>>{});

inline const JobKind& jobKind(const Request& request) { return kJobKinds[request.index()]; }

// The request's kind: its JSON "kind" and CLI command ("render", "sample", "grade", ...).
inline const char* kindName(const Request& request) { return jobKind(request).name.data(); }

// Whether a request of this kind needs a GL context.
inline bool needsGl(const Request& request) { return jobKind(request).needsGl; }

// "render, animate, sample, ...": every kind's name, for messages.
inline std::string jobKindNames() {
    std::string names;
    for (const JobKind& kind : kJobKinds) names += (names.empty() ? "" : ", ") + std::string(kind.name);
    return names;
}

// Calls make((T*)nullptr) for the request type T whose kind is `name` (or was), and returns its
// result; `none` when no kind has that name.
template <class Result, class Make> Result withJobKind(std::string_view name, Make&& make, Result none) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        Result result = std::move(none);
        (void)((kJobKinds[I].name == name || (!kJobKinds[I].formerName.empty() && kJobKinds[I].formerName == name)
                    ? (result = make(static_cast<std::variant_alternative_t<I, Request>*>(nullptr)), true)
                    : false) ||
               ...);
        return result;
    }
    (std::make_index_sequence<kJobKinds.size()>{});
}

} // namespace sdfwb::values
