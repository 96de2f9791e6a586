#include <renderer/NoiseTexture.h>

#include <meshfield/MeshQuery.h>

#include "GlObjects.h"

#include <core/Hash.h>
#include <core/Log.h>
#include <renderer/ImageIO.h>
#include <shaders/ShaderComposer.h>

#include <algorithm>
#include <cstdlib>

namespace sdfwb::renderer {

// Each byte a hash of its index, with the samplers' finaliser: consecutive texels are unrelated.
std::vector<std::uint8_t> noiseTexels() {
    std::vector<std::uint8_t> texels(std::size_t(kNoiseTextureSize) * kNoiseTextureSize * 4);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = std::uint8_t(scramble32(std::uint32_t(i) ^ 0x5bd1e995u) >> 24);
    return texels;
}

std::vector<std::uint8_t> shadertoyNoiseTexels() {
    std::vector<std::uint8_t> texels = noiseTexels();
    const std::vector<std::uint8_t> base = texels;
    const int n = kNoiseTextureSize;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const std::size_t to = (std::size_t(y) * std::size_t(n) + std::size_t(x)) * 4;
            const int fromX = (x - kShadertoyNoiseShiftX + n) % n, fromY = (y - kShadertoyNoiseShiftY + n) % n;
            const std::size_t from = (std::size_t(fromY) * std::size_t(n) + std::size_t(fromX)) * 4;
            texels[to + 1] = base[from + 0];
            texels[to + 3] = base[from + 2];
        }
    return texels;
}

namespace {

// Makes a repeating 2D texture from RGBA8 rows, bottom row first.
GlTexture makeTexture(int width, int height, const std::uint8_t* texels, bool mipmaps) {
    GLuint id = 0;
    glGenTextures(1, &id);
    GlTexture texture(id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4); // the default, which others sharing the context assume
    if (mipmaps) glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    return texture;
}

// A cube map with the same RGBA8 image on each of its six faces.
GlTexture makeCubeTexture(int width, int height, const std::uint8_t* texels) {
    GLuint id = 0;
    glGenTextures(1, &id);
    GlTexture texture(id);
    glBindTexture(GL_TEXTURE_CUBE_MAP, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int face = 0; face < 6; ++face)
        glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     texels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return texture;
}

// Whether `program`'s uniform `name` is a samplerCube.
bool isCubeSampler(GLuint program, const char* name) {
    const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, name);
    if (index == GL_INVALID_INDEX) return false;
    const GLenum property = GL_TYPE;
    GLint type = 0;
    glGetProgramResourceiv(program, GL_UNIFORM, index, 1, &property, 1, nullptr, &type);
    return type == GL_SAMPLER_CUBE;
}

GlTexture makeNoiseTexture() {
    const std::vector<std::uint8_t> texels = noiseTexels();
    return makeTexture(kNoiseTextureSize, kNoiseTextureSize, texels.data(), false);
}

void bindUnit(int unit, const GlTexture& texture, GLenum target = GL_TEXTURE_2D) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(target, texture.id());
    glActiveTexture(GL_TEXTURE0);
}

} // namespace

void SdfTextures::reset() {
    mesh.reset();
    meshNodes.reset();
    meshTriangles.reset();
    meshPseudonormals.reset();
    noise.reset();
    for (GlTexture& channel : channels) channel.reset();
    channelFiles = {};
}

void SdfTextures::release() {
    mesh.reset();
    meshNodes.release();
    meshTriangles.release();
    meshPseudonormals.release();
    noise.release();
    for (GlTexture& channel : channels) channel.release();
    channelFiles = {};
}

namespace {

GlBuffer storageBuffer(const std::vector<float>& data) {
    GLuint id = 0;
    glGenBuffers(1, &id);
    GlBuffer buffer(id);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, id);
    // An empty buffer still gets a few bytes: binding a zero-sized store is an error.
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(std::max<std::size_t>(16, data.size() * sizeof(float))),
                 data.empty() ? nullptr : data.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return buffer;
}

// The GLSL field's sign lattice (MeshQuery::signLattice): `wanted`, or 33^3 points (level 5).
// SDFWB_MESH_SIGN_LEVEL=2..7 sets it for every caller.
int glslSignLevel(int wanted) {
    if (const char* level = std::getenv("SDFWB_MESH_SIGN_LEVEL"); level && *level) return std::clamp(std::atoi(level), 2, 7);
    return wanted > 0 ? std::clamp(wanted, 2, 7) : 5;
}

void bindMesh(SdfTextures& textures, const std::shared_ptr<const meshfield::MeshField>& mesh) {
    const bool winding = mesh->options.sign == meshfield::SignMethod::Winding;
    // Only winding numbers have the lattice, and only a program that computes signs reads it.
    const int level = winding && textures.meshSignLevel >= 0 ? glslSignLevel(textures.meshSignLevel) : 0;
    if (textures.mesh != mesh || textures.uploadedSignLevel != level) {
        textures.mesh = mesh;
        textures.uploadedSignLevel = level;
        // The binary hierarchy, then the four-wide one (SDFWB_MESH_WIDE: where it starts).
        std::vector<float> nodes = mesh->nodes;
        nodes.insert(nodes.end(), mesh->wideNodes.begin(), mesh->wideNodes.end());
        // Winding numbers: then the sign lattice (SDFWB_MESH_SIGNS: where it starts).
        if (level > 0) {
            const std::vector<float> signs = meshfield::meshQuery(mesh)->signLattice(level);
            nodes.insert(nodes.end(), signs.begin(), signs.end());
        }
        nodes.resize((nodes.size() + 3) / 4 * 4, 0.0f); // whole vec4s: the shader reads the last one whole
        textures.meshNodes = storageBuffer(nodes);
        textures.meshTriangles = storageBuffer(mesh->triangles);
        textures.meshPseudonormals = storageBuffer(mesh->pseudonormals);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shaders::kMeshNodesBinding, textures.meshNodes.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shaders::kMeshTrianglesBinding, textures.meshTriangles.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shaders::kMeshPseudonormalsBinding, textures.meshPseudonormals.id());
}

} // namespace

void bindSdfTextures(GLuint program, SdfTextures& textures, const std::array<std::string, shaders::kShadertoyChannels>& files,
                     const std::shared_ptr<const meshfield::MeshField>& mesh) {
    if (mesh) bindMesh(textures, mesh);
    if (glGetUniformLocation(program, "g3d_uniformRandom") >= 0) {
        if (!textures.noise) textures.noise = makeNoiseTexture();
        bindUnit(shaders::kNoiseTextureUnit, textures.noise);
    }
    static const char* const names[shaders::kShadertoyChannels] = {"iChannel0", "iChannel1", "iChannel2", "iChannel3"};
    static const char* const resolutions[shaders::kShadertoyChannels] = {"iChannelResolution[0]", "iChannelResolution[1]",
                                                                         "iChannelResolution[2]", "iChannelResolution[3]"};
    for (int n = 0; n < shaders::kShadertoyChannels; ++n) {
        if (glGetUniformLocation(program, names[n]) < 0) continue;
        const std::size_t i = std::size_t(n);
        const bool cube = isCubeSampler(program, names[n]);
        if (!textures.channels[i] || textures.channelFiles[i] != files[i] || textures.channelCubes[i] != cube) {
            textures.channelCubes[i] = cube;
            textures.channels[i].reset();
            textures.channelFiles[i] = files[i];
            textures.channelSizes[i] = glm::vec2(float(kNoiseTextureSize));
            if (!files[i].empty()) {
                if (auto image = readImage(files[i])) {
                    // Shadertoy shows images upright: v = 0 is the image's bottom row.
                    const std::size_t row = std::size_t(image->width) * 4;
                    std::vector<std::uint8_t> flipped(image->rgba.size());
                    for (int y = 0; y < image->height; ++y)
                        std::copy_n(image->rgba.data() + std::size_t(image->height - 1 - y) * row, row,
                                    flipped.data() + std::size_t(y) * row);
                    textures.channels[i] = cube ? makeCubeTexture(image->width, image->height, flipped.data())
                                                : makeTexture(image->width, image->height, flipped.data(), true);
                    textures.channelSizes[i] = glm::vec2(float(image->width), float(image->height));
                } else {
                    log::warning("render", std::string(names[n]) + ": " + image.error().message + "; using the noise texture");
                }
            }
            if (!textures.channels[i]) {
                const std::vector<std::uint8_t> texels = shadertoyNoiseTexels();
                textures.channels[i] = cube ? makeCubeTexture(kNoiseTextureSize, kNoiseTextureSize, texels.data())
                                            : makeTexture(kNoiseTextureSize, kNoiseTextureSize, texels.data(), false);
            }
        }
        bindUnit(shaders::kChannelTextureUnit + n, textures.channels[i], cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D);
        if (GLint at = glGetUniformLocation(program, resolutions[n]); at >= 0)
            glProgramUniform3f(program, at, textures.channelSizes[i].x, textures.channelSizes[i].y, 1.0f);
    }
}

} // namespace sdfwb::renderer
