#include "app/gui/panels/view/scene_renderer.h"

#include <QMatrix4x4>
#include <QVector3D>

#include <cstddef>

namespace rbw::view {

namespace {

// --- GLSL 330 core sources ---

// A full-screen triangle from gl_VertexID (no vertex buffer): a soft vertical gradient.
const char* kBackgroundVs = R"(#version 330 core
out float v_t;
void main() {
    vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    v_t = 0.5 * p.y + 0.5;
    gl_Position = vec4(p, 0.0, 1.0);
})";
const char* kBackgroundFs = R"(#version 330 core
in float v_t;
out vec4 fragColour;
void main() {
    vec3 bottom = vec3(0.80, 0.84, 0.89);
    vec3 top = vec3(0.97, 0.98, 0.99);
    fragColour = vec4(mix(bottom, top, clamp(v_t, 0.0, 1.0)), 1.0);
})";

// Lambert with ambient: c (k_a + k_d max(n . l, 0) + k_s (1 + n_y)/2), a little sky light from +y.
const char* kLitVs = R"(#version 330 core
layout(location = 0) in vec3 a_p;
layout(location = 1) in vec3 a_n;
layout(location = 2) in vec4 a_c;
uniform mat4 u_pv;
out vec3 v_n;
out vec4 v_c;
void main() {
    v_n = a_n;
    v_c = a_c;
    gl_Position = u_pv * vec4(a_p, 1.0);
})";
const char* kLitFs = R"(#version 330 core
in vec3 v_n;
in vec4 v_c;
uniform vec3 u_light;
uniform float u_alpha;
out vec4 fragColour;
void main() {
    vec3 n = normalize(v_n);
    float diffuse = max(dot(n, u_light), 0.0);
    float sky = 0.5 + 0.5 * n.y;
    float k = 0.42 + 0.50 * diffuse + 0.12 * sky;
    fragColour = vec4(v_c.rgb * k, v_c.a * u_alpha);
})";

const char* kLineVs = R"(#version 330 core
layout(location = 0) in vec3 a_p;
layout(location = 1) in vec4 a_c;
uniform mat4 u_pv;
out vec4 v_c;
void main() {
    v_c = a_c;
    gl_Position = u_pv * vec4(a_p, 1.0);
})";
const char* kLineFs = R"(#version 330 core
in vec4 v_c;
out vec4 fragColour;
void main() { fragColour = v_c; })";

// A checker of 1 m cells with anti-aliased grid lines (screen-space width from fwidth).
const char* kPlaneVs = R"(#version 330 core
layout(location = 0) in vec3 a_p;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_c;
uniform mat4 u_pv;
out vec2 v_uv;
out vec4 v_c;
void main() {
    v_uv = a_uv;
    v_c = a_c;
    gl_Position = u_pv * vec4(a_p, 1.0);
})";
const char* kPlaneFs = R"(#version 330 core
in vec2 v_uv;
in vec4 v_c;
out vec4 fragColour;
void main() {
    float checker = mod(floor(v_uv.x) + floor(v_uv.y), 2.0);
    vec2 w = max(fwidth(v_uv), vec2(1e-6));
    vec2 d = abs(fract(v_uv - 0.5) - 0.5) / w;
    float line = 1.0 - clamp(min(d.x, d.y), 0.0, 1.0);
    vec3 c = v_c.rgb * mix(1.08, 0.92, checker);
    c = mix(c, v_c.rgb * 0.6, 0.6 * line);
    fragColour = vec4(c, v_c.a + 0.25 * line * v_c.a);
})";

QMatrix4x4 toQt(const Eigen::Matrix4d& m)
{
    // QMatrix4x4(const float*) reads row-major.
    float values[16];
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) values[4 * r + c] = float(m(r, c));
    }
    return QMatrix4x4(values);
}

void upload(QOpenGLBuffer& vbo, const void* data, size_t bytes)
{
    vbo.bind();
    // Orphan the old storage, then fill: the driver need not wait for the last frame.
    vbo.allocate(static_cast<int>(bytes));
    if (bytes > 0) vbo.write(0, data, static_cast<int>(bytes));
}

} // namespace

SceneRenderer::SceneRenderer() = default;
SceneRenderer::~SceneRenderer() = default;

bool SceneRenderer::buildProgram(Pass& pass, const char* name, const char* vertex, const char* fragment,
                                 QString* error)
{
    pass.program = std::make_unique<QOpenGLShaderProgram>();
    if (!pass.program->addShaderFromSourceCode(QOpenGLShader::Vertex, vertex) ||
        !pass.program->addShaderFromSourceCode(QOpenGLShader::Fragment, fragment) || !pass.program->link()) {
        if (error) *error = QStringLiteral("the %1 shader does not compile: %2").arg(name, pass.program->log());
        return false;
    }
    if (!pass.vao.create()) {
        if (error) *error = QStringLiteral("cannot create a vertex array object");
        return false;
    }
    return true;
}

bool SceneRenderer::initialize(QString* error)
{
    initializeOpenGLFunctions();
    if (!buildProgram(background_, "background", kBackgroundVs, kBackgroundFs, error) ||
        !buildProgram(lit_, "lit", kLitVs, kLitFs, error) || !buildProgram(lines_, "line", kLineVs, kLineFs, error) ||
        !buildProgram(planes_, "plane", kPlaneVs, kPlaneFs, error)) {
        return false;
    }
    // Vertex layouts: one interleaved buffer per pass, attributes as in the shaders.
    auto layout = [&](Pass& pass, auto setup) {
        pass.vbo.setUsagePattern(QOpenGLBuffer::StreamDraw);
        if (!pass.vbo.create()) return false;
        pass.vao.bind();
        pass.vbo.bind();
        setup();
        pass.vao.release();
        return true;
    };
    const bool ok =
        layout(lit_,
               [&] {
                   const GLsizei stride = sizeof(LitVertex);
                   glEnableVertexAttribArray(0);
                   glEnableVertexAttribArray(1);
                   glEnableVertexAttribArray(2);
                   glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LitVertex, p)));
                   glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LitVertex, n)));
                   glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LitVertex, c)));
               }) &&
        layout(lines_,
               [&] {
                   const GLsizei stride = sizeof(LineVertex);
                   glEnableVertexAttribArray(0);
                   glEnableVertexAttribArray(1);
                   glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LineVertex, p)));
                   glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(LineVertex, c)));
               }) &&
        layout(planes_, [&] {
            const GLsizei stride = sizeof(PlaneVertex);
            glEnableVertexAttribArray(0);
            glEnableVertexAttribArray(1);
            glEnableVertexAttribArray(2);
            glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(PlaneVertex, p)));
            glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(PlaneVertex, uv)));
            glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(PlaneVertex, c)));
        });
    if (!ok) {
        if (error) *error = QStringLiteral("cannot create vertex buffers");
        return false;
    }
    initialized_ = true;
    return true;
}

void SceneRenderer::draw(const FrameGeometry& geometry, const Eigen::Matrix4d& PV, const Vec3& forward_W,
                         const Vec3& right_W, const Vec3& up_W)
{
    if (!initialized_) return;
    const QMatrix4x4 pv = toQt(PV);

    // A fresh depth buffer every frame (QOpenGLWidget does not clear it), then the
    // background gradient, which writes no depth.
    glDepthMask(GL_TRUE);
    glClearColor(0.9f, 0.92f, 0.95f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    background_.program->bind();
    background_.vao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    background_.vao.release();

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    // Opaque lit triangles: boxes, then arrows and markers (one buffer: boxes first).
    // Key light from above-left behind the viewer.
    const Vec3 light_W = (-forward_W + 0.8 * up_W - 0.4 * right_W).normalized();
    const GLsizei boxCount = static_cast<GLsizei>(geometry.lit.size());
    const GLsizei overlayCount = static_cast<GLsizei>(geometry.overlay.size());
    if (boxCount + overlayCount > 0) {
        lit_.program->bind();
        lit_.program->setUniformValue("u_pv", pv);
        lit_.program->setUniformValue("u_light", QVector3D(float(light_W.x()), float(light_W.y()), float(light_W.z())));
        lit_.program->setUniformValue("u_alpha", 1.0f);
        lit_.vao.bind();
        lit_.vbo.bind();
        const size_t boxBytes = geometry.lit.size() * sizeof(LitVertex);
        const size_t overlayBytes = geometry.overlay.size() * sizeof(LitVertex);
        lit_.vbo.allocate(static_cast<int>(boxBytes + overlayBytes));
        if (boxBytes > 0) lit_.vbo.write(0, geometry.lit.data(), static_cast<int>(boxBytes));
        if (overlayBytes > 0) lit_.vbo.write(static_cast<int>(boxBytes), geometry.overlay.data(), static_cast<int>(overlayBytes));
        glDrawArrays(GL_TRIANGLES, 0, boxCount + overlayCount);
        // X-ray: the parts of arrows and markers hidden inside or behind boxes (a contact
        // point lies inside both boxes) are drawn again at 60 % where they failed the
        // depth test, so no arrow is ever hidden by a body, yet one can tell it is inside.
        if (overlayCount > 0) {
            glDepthFunc(GL_GREATER);
            glDepthMask(GL_FALSE);
            lit_.program->setUniformValue("u_alpha", 0.6f);
            glDrawArrays(GL_TRIANGLES, boxCount, overlayCount);
            glDepthFunc(GL_LEQUAL);
            glDepthMask(GL_TRUE);
        }
        lit_.vao.release();
    }

    // Lines: edges, body axes, trails, spring.
    if (!geometry.lines.empty()) {
        lines_.program->bind();
        lines_.program->setUniformValue("u_pv", pv);
        lines_.vao.bind();
        upload(lines_.vbo, geometry.lines.data(), geometry.lines.size() * sizeof(LineVertex));
        glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(geometry.lines.size()));
        lines_.vao.release();
    }

    // Planes last, translucent, not writing depth, pushed slightly back so that box
    // edges lying on them stay visible.
    if (!geometry.planes.empty()) {
        glDepthMask(GL_FALSE);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        planes_.program->bind();
        planes_.program->setUniformValue("u_pv", pv);
        planes_.vao.bind();
        upload(planes_.vbo, geometry.planes.data(), geometry.planes.size() * sizeof(PlaneVertex));
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(geometry.planes.size()));
        planes_.vao.release();
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDepthMask(GL_TRUE);
    }
    planes_.program->release();

    // Leave the state QPainter expects for the overlay.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
}

void SceneRenderer::release()
{
    for (Pass* pass : {&background_, &lit_, &lines_, &planes_}) {
        pass->vbo.destroy();
        pass->vao.destroy();
        pass->program.reset();
    }
    initialized_ = false;
}

} // namespace rbw::view
