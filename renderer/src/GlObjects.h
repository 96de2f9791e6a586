#pragma once
// Move-only owners of GL names. Private to renderer/: other modules see plain integers at most.
// A default-constructed object owns nothing ("not created yet"). Destroy or reset() them while
// their context is current; release() forgets the name without a GL call (context already gone).

#include <epoxy/gl.h>

#include <shaders/Diagnostic.h>
#include <shaders/Parameters.h>
#include <shaders/SdfSource.h>
#include <shaders/ShaderComposer.h>

#include <glm/vec2.hpp>

#include <array>
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sdfwb::renderer {

// Live names owned through GlName, process-wide (renderer::liveGlObjects() reads it).
void countGlObject(int delta);

template <void (*Delete)(GLuint)> class GlName {
public:
    GlName() = default;
    explicit GlName(GLuint id) : m_id(id) {
        if (m_id) countGlObject(1);
    }
    ~GlName() { reset(); }
    GlName(GlName&& other) noexcept : m_id(std::exchange(other.m_id, 0)) {}
    GlName& operator=(GlName&& other) noexcept {
        if (this != &other) {
            reset();
            m_id = std::exchange(other.m_id, 0);
        }
        return *this;
    }
    GlName(const GlName&) = delete;
    GlName& operator=(const GlName&) = delete;

    GLuint id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }
    void reset() {
        if (m_id) {
            Delete(m_id);
            countGlObject(-1);
        }
        m_id = 0;
    }
    void release() { // the context is gone, and the name with it
        if (m_id) countGlObject(-1);
        m_id = 0;
    }

private:
    GLuint m_id = 0;
};

void deleteProgram(GLuint id);
void deleteShader(GLuint id);
void deleteVertexArray(GLuint id);
void deleteFramebuffer(GLuint id);
void deleteRenderbuffer(GLuint id);
void deleteTexture(GLuint id);
void deleteBuffer(GLuint id);
void deleteProgramPipeline(GLuint id);
void deleteQuery(GLuint id);

using GlProgram = GlName<deleteProgram>;
using GlShader = GlName<deleteShader>;
using GlVertexArray = GlName<deleteVertexArray>;
using GlFramebuffer = GlName<deleteFramebuffer>;
using GlRenderbuffer = GlName<deleteRenderbuffer>;
using GlTexture = GlName<deleteTexture>;
using GlBuffer = GlName<deleteBuffer>;
using GlProgramPipeline = GlName<deleteProgramPipeline>;
using GlQuery = GlName<deleteQuery>;

// A width x height texture (RGBA8 unless asked), one level, `filter` both ways; left unbound.
GlTexture makeColorTexture(int width, int height, GLenum filter, GLenum format = GL_RGBA8);
// Such a texture and a framebuffer around it (colour attachment 0), left bound.
void makeColorTarget(int width, int height, GLenum filter, GlTexture& texture, GlFramebuffer& framebuffer,
                     GLenum format = GL_RGBA8);

// GPU time of the commands between begin() and end() (a GL_TIME_ELAPSED query; queries of one
// target do not nest): milliseconds() waits for the result, -1 when none was taken or when it
// exceeds `wall`, the wall time that brackets the commands and the wait for them (llvmpipe's
// first query after a program's link reads hours).
class GpuTimer {
public:
    void begin() {
        if (!m_query) {
            GLuint id = 0;
            glGenQueries(1, &id);
            m_query = GlQuery(id);
        }
        glBeginQuery(GL_TIME_ELAPSED, m_query.id());
        m_running = true;
    }
    void end() {
        if (!m_running) return;
        glEndQuery(GL_TIME_ELAPSED);
        m_running = false;
        m_taken = true;
    }
    double milliseconds(double wall) {
        if (!m_taken) return -1.0;
        GLuint64 nanoseconds = 0;
        glGetQueryObjectui64v(m_query.id(), GL_QUERY_RESULT, &nanoseconds);
        m_taken = false;
        const double milliseconds = double(nanoseconds) * 1e-6;
        return milliseconds <= wall ? milliseconds : -1.0;
    }
    void reset() { m_query.reset(), m_running = m_taken = false; }
    void release() { m_query.release(), m_running = m_taken = false; }

private:
    GlQuery m_query;
    bool m_running = false, m_taken = false;
};

// A compiled shader stage and what the driver said about it, mapped to the user's files.
struct CompiledShader {
    GlShader shader;
    std::vector<shaders::Diagnostic> diagnostics;
};

// Compiles one composed stage (a current context is needed). Failure shows as errors in
// `diagnostics`, never as a silent empty shader.
CompiledShader compileShader(GLenum type, const shaders::ComposedShader& composed);

// Warnings for the loops of `composed` that the current context's driver would cut short
// (shaders/LoopLimits.h: llvmpipe stops every loop after 65535 iterations), each logged once per
// process; records the driver's limit for the editor's checks.
std::vector<shaders::Diagnostic> driverLoopWarnings(const shaders::PreparedSdf& sdf, const shaders::ComposedShader& composed);

// Links compiled stages into a program. On failure: an empty program, and the driver's log in `log`.
// A separable program is one stage of a program pipeline (glUseProgramStages).
GlProgram linkProgram(std::initializer_list<GLuint> shaders, std::string& log, bool separable = false);

// The textures an SDF's program may read: the G3D noise texture (g3d_uniformRandom) and
// Shadertoy's iChannel0..3. Each is made on the first draw that reads it.
struct SdfTextures {
    GlTexture noise;
    std::array<GlTexture, shaders::kShadertoyChannels> channels;
    std::array<std::string, shaders::kShadertoyChannels> channelFiles; // what each holds ("": the noise texels)
    std::array<glm::vec2, shaders::kShadertoyChannels> channelSizes{};
    std::array<bool, shaders::kShadertoyChannels> channelCubes{}; // a cube map (the program's samplerCube)
    // A mesh SDF's buffers (shaders/mesh/mesh_field.glsl), uploaded once per mesh.
    std::shared_ptr<const meshfield::MeshField> mesh;
    GlBuffer meshNodes;
    GlBuffer meshTriangles;
    GlBuffer meshPseudonormals;
    // The GLSL field's sign lattice (MeshQuery::signLattice): the level a caller asks for (0: the
    // default, 5), and the level uploaded with the nodes. -1: none (a program that only places
    // points on the mesh, the CPU engine computing their values, reads no sign).
    int meshSignLevel = 0;
    int uploadedSignLevel = 0;
    void reset();
    void release();
};

// Binds what `program` reads: the noise texture to shaders::kNoiseTextureUnit (see NoiseTexture.h),
// iChannelN to shaders::kChannelTextureUnit + N, holding the image `files[N]` (rows from the
// bottom, as Shadertoy shows images; mipmapped) or, when that is empty or unreadable (logged), the
// noise texels (a channel the program declares samplerCube: a cube map with that image on each
// face); sets iChannelResolution to the sizes; binds a mesh SDF's buffers to
// shaders::kMesh*Binding (uploaded on first use). Needs a current context.
void bindSdfTextures(GLuint program, SdfTextures& textures, const std::array<std::string, shaders::kShadertoyChannels>& files,
                     const std::shared_ptr<const meshfield::MeshField>& mesh);

// Sets the SDF's parameter uniforms of the program in use (glUseProgram done); `locate(name)`
// gives a uniform's location (the tracer's cached lookup, once a frame); a parameter the compiler
// optimised away has no location and is skipped.
template <class Locate> void applyParameters(const std::vector<shaders::ParameterSetting>& parameters, Locate locate) {
    for (const shaders::ParameterSetting& p : parameters) {
        const GLint location = locate(p.name.c_str());
        if (location < 0) continue;
        const float* v = p.value.data();
        switch (p.type) {
        case shaders::ParameterType::Float:
            glUniform1f(location, v[0]);
            break;
        case shaders::ParameterType::Int:
            glUniform1i(location, GLint(v[0]));
            break;
        case shaders::ParameterType::Bool:
            glUniform1i(location, v[0] != 0.0f ? 1 : 0);
            break;
        case shaders::ParameterType::Vec2:
            glUniform2fv(location, 1, v);
            break;
        case shaders::ParameterType::Vec3:
            glUniform3fv(location, 1, v);
            break;
        case shaders::ParameterType::Vec4:
            glUniform4fv(location, 1, v);
            break;
        }
    }
}

} // namespace sdfwb::renderer
