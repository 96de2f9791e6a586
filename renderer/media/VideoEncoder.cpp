// MP4 files through the FFmpeg libraries: the video half of libsdfwb_media.so (see MediaApi.h).
#include "MediaApi.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <random>

namespace sdfwb::renderer::media {
namespace fs = std::filesystem;

namespace {

std::string ffmpegError(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

} // namespace

class H264Encoder final : public VideoEncoder {
public:
    fs::path target;
    fs::path temporary;
    AVFormatContext* format = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* packet = nullptr;
    SwsContext* scaler = nullptr;
    int sourceWidth = 0, sourceHeight = 0;
    int frameCount = 0;
    bool finished = false;

    ~H264Encoder() override {
        if (scaler) sws_freeContext(scaler);
        if (frame) av_frame_free(&frame);
        if (packet) av_packet_free(&packet);
        if (codec) avcodec_free_context(&codec);
        if (format) {
            if (format->pb) avio_closep(&format->pb);
            avformat_free_context(format);
        }
        if (!finished && !temporary.empty()) {
            std::error_code ec;
            fs::remove(temporary, ec);
        }
    }

    // Sends a frame (or null to flush) and writes every packet the encoder has ready.
    Expected<void> encode(AVFrame* input) {
        int result = avcodec_send_frame(codec, input);
        if (result < 0) return makeError(target.string() + ": encoding failed: " + ffmpegError(result));
        while (true) {
            result = avcodec_receive_packet(codec, packet);
            if (result == AVERROR(EAGAIN) || result == AVERROR_EOF) return {};
            if (result < 0) return makeError(target.string() + ": encoding failed: " + ffmpegError(result));
            // Every frame lasts one frame period. Without a duration the MP4 muxer gives the last
            // packet none, and players (and FFmpeg's own decoder) drop the last frame.
            if (packet->duration <= 0) packet->duration = 1;
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            result = av_interleaved_write_frame(format, packet);
            av_packet_unref(packet);
            if (result < 0) return makeError(target.string() + ": write failed: " + ffmpegError(result));
        }
    }

    Expected<void> addFrame(const Image& image) override {
        if (image.width != sourceWidth || image.height != sourceHeight)
            return makeError(target.string() + ": frame is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             ", the video " + std::to_string(sourceWidth) + "x" + std::to_string(sourceHeight));
        int result = av_frame_make_writable(frame);
        if (result < 0) return makeError(target.string() + ": " + ffmpegError(result));
        const std::uint8_t* source[1] = {image.rgba.data()};
        const int stride[1] = {image.width * 4};
        sws_scale(scaler, source, stride, 0, image.height, frame->data, frame->linesize);
        frame->pts = frameCount++;
        return encode(frame);
    }

    Expected<void> finish() override {
        if (frameCount == 0) return makeError(target.string() + ": no frames to write");
        if (auto ok = encode(nullptr); !ok) return ok;
        int result = av_write_trailer(format);
        if (result < 0) return makeError(target.string() + ": " + ffmpegError(result));
        avio_closep(&format->pb);
        std::error_code ec;
        fs::rename(temporary, target, ec);
        if (ec) return makeError(target.string() + ": cannot move the finished video into place: " + ec.message());
        finished = true;
        return {};
    }

    int frames() const override { return frameCount; }
};

Expected<std::unique_ptr<VideoEncoder>> openVideo(const fs::path& path, int width, int height, int framesPerSecond,
                                                  const FileMetadata& metadata) {
    if (width < 2 || height < 2) return makeError(path.string() + ": video frames must be at least 2x2");
    if (framesPerSecond < 1 || framesPerSecond > 240) return makeError(path.string() + ": frame rate must be 1..240");
    auto writer = std::make_unique<H264Encoder>();
    H264Encoder& v = *writer;
    v.target = path;
    v.sourceWidth = width;
    v.sourceHeight = height;
    fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::random_device random;
    v.temporary = folder / ("." + path.stem().string() + ".partial" + std::to_string(random()) + ".mp4");

    av_log_set_level(AV_LOG_ERROR); // the encoder's statistics are noise on a terminal
    const AVCodec* encoder = avcodec_find_encoder_by_name("libx264");
    if (!encoder) encoder = avcodec_find_encoder(AV_CODEC_ID_H264);
    if (!encoder) return makeError(path.string() + ": this FFmpeg has no H.264 encoder");
    int result = avformat_alloc_output_context2(&v.format, nullptr, "mp4", v.temporary.c_str());
    if (result < 0 || !v.format) return makeError(path.string() + ": cannot create an MP4 container: " + ffmpegError(result));
    v.stream = avformat_new_stream(v.format, nullptr);
    v.codec = avcodec_alloc_context3(encoder);
    if (!v.stream || !v.codec) return makeError(path.string() + ": out of memory");
    v.codec->width = width & ~1;
    v.codec->height = height & ~1;
    v.codec->time_base = AVRational{1, framesPerSecond};
    v.codec->framerate = AVRational{framesPerSecond, 1};
    v.codec->pix_fmt = AV_PIX_FMT_YUV420P;
    v.codec->gop_size = 2 * framesPerSecond;
    v.codec->max_b_frames = 2;
    if (v.format->oformat->flags & AVFMT_GLOBALHEADER) v.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    av_opt_set(v.codec->priv_data, "preset", "medium", 0);
    av_opt_set(v.codec->priv_data, "crf", "18", 0);
    if ((result = avcodec_open2(v.codec, encoder, nullptr)) < 0)
        return makeError(path.string() + ": cannot open the H.264 encoder: " + ffmpegError(result));
    if ((result = avcodec_parameters_from_context(v.stream->codecpar, v.codec)) < 0)
        return makeError(path.string() + ": " + ffmpegError(result));
    v.stream->time_base = v.codec->time_base;
    if ((result = avio_open(&v.format->pb, v.temporary.c_str(), AVIO_FLAG_WRITE)) < 0)
        return makeError(path.string() + ": cannot write in " + folder.string() + ": " + ffmpegError(result));
    // The MP4 muxer keeps only the tags it knows unless asked to write every one (ours are
    // sdfwb_... keys, read back by ffprobe -show_format).
    for (const auto& [key, value] : metadata) av_dict_set(&v.format->metadata, key.c_str(), value.c_str(), 0);
    AVDictionary* options = nullptr;
    if (!metadata.empty()) av_dict_set(&options, "movflags", "use_metadata_tags", 0);
    result = avformat_write_header(v.format, &options);
    av_dict_free(&options);
    if (result < 0) return makeError(path.string() + ": " + ffmpegError(result));
    v.frame = av_frame_alloc();
    v.packet = av_packet_alloc();
    if (!v.frame || !v.packet) return makeError(path.string() + ": out of memory");
    v.frame->format = v.codec->pix_fmt;
    v.frame->width = v.codec->width;
    v.frame->height = v.codec->height;
    if ((result = av_frame_get_buffer(v.frame, 0)) < 0) return makeError(path.string() + ": " + ffmpegError(result));
    v.scaler = sws_getContext(width, height, AV_PIX_FMT_RGBA, v.codec->width, v.codec->height, AV_PIX_FMT_YUV420P, SWS_BICUBIC,
                              nullptr, nullptr, nullptr);
    if (!v.scaler) return makeError(path.string() + ": cannot set up colour conversion");
    return std::unique_ptr<VideoEncoder>(std::move(writer));
}

} // namespace sdfwb::renderer::media
