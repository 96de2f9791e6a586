#include <renderer/NoiseTexture.h>

#include "GlObjects.h"

#include <core/Hash.h>
#include <shaders/ShaderComposer.h>

namespace sdfwb::renderer {

// Each byte a hash of its index, with the samplers' finaliser: consecutive texels are unrelated.
std::vector<std::uint8_t> noiseTexels() {
    std::vector<std::uint8_t> texels(std::size_t(kNoiseTextureSize) * kNoiseTextureSize * 4);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = std::uint8_t(scramble32(std::uint32_t(i) ^ 0x5bd1e995u) >> 24);
    return texels;
}

void bindNoiseTextureIfUsed(GLuint program, GlTexture& texture) {
    if (glGetUniformLocation(program, "g3d_uniformRandom") < 0) return;
    if (!texture) {
        GLuint id = 0;
        glGenTextures(1, &id);
        texture = GlTexture(id);
        glBindTexture(GL_TEXTURE_2D, id);
        const std::vector<std::uint8_t> texels = noiseTexels();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kNoiseTextureSize, kNoiseTextureSize, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     texels.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4); // the default, which others sharing the context assume
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    }
    glActiveTexture(GLenum(GL_TEXTURE0 + shaders::kNoiseTextureUnit));
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glActiveTexture(GL_TEXTURE0);
}

} // namespace sdfwb::renderer
