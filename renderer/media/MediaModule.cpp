// The one symbol libsdfwb_media.so exports: its table of functions (MediaApi.h).

#include "MediaApi.h"

namespace {

using namespace sdfwb::renderer;

const media::Api table{
    media::kAbiVersion,
    static_cast<sdfwb::Expected<void> (*)(const std::filesystem::path&, const Image&)>(&media::writeImage),
    static_cast<sdfwb::Expected<void> (*)(const std::filesystem::path&, const FloatImage&)>(&media::writeImage),
    static_cast<sdfwb::Expected<void> (*)(Image&, const std::string&)>(&media::drawLabel),
    static_cast<sdfwb::Expected<void> (*)(FloatImage&, const std::string&)>(&media::drawLabel),
    &media::readFloatImage,
    &media::readImage,
    &media::canWriteImageExtension,
    &media::openVideo,
};

} // namespace

extern "C" __attribute__((visibility("default"))) const media::Api* sdfwb_media_api() { return &table; }
