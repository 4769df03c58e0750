// The GPU side of the 3D view: four small GLSL 330 core programs (background
// gradient, lit triangles, lines, checkered planes) and one vertex buffer per kind.
// Each frame uploads the FrameGeometry and draws it in four draw calls, so the cost
// does not grow with the number of draw calls per body.
//
// Needs a current OpenGL 3.3 core context for initialize(), draw() and release().
#pragma once

#include "app/gui/panels/view/frame_geometry.h"

#include <Eigen/Core>

#include <QOpenGLBuffer>
#include <QOpenGLExtraFunctions>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QString>

#include <memory>

namespace rbw::view {

class SceneRenderer : protected QOpenGLExtraFunctions {
public:
    SceneRenderer();
    ~SceneRenderer();

    // Compiles the shaders and creates the buffers. False, with a readable reason in
    // *error, if the context cannot run them.
    bool initialize(QString* error);
    bool isInitialized() const { return initialized_; }

    // clip = PV p_W; eye_W and the camera axes set the lighting (a key light from
    // above-left of the viewer, so faces turned to the camera are always lit).
    void draw(const FrameGeometry& geometry, const Eigen::Matrix4d& PV, const Vec3& forward_W, const Vec3& right_W,
              const Vec3& up_W);

    // Frees GL objects; call with the context current (before it goes away).
    void release();

private:
    struct Pass {
        std::unique_ptr<QOpenGLShaderProgram> program;
        QOpenGLVertexArrayObject vao;
        QOpenGLBuffer vbo{QOpenGLBuffer::VertexBuffer};
    };
    bool buildProgram(Pass& pass, const char* name, const char* vertex, const char* fragment, QString* error);

    Pass background_;
    Pass lit_;
    Pass lines_;
    Pass planes_;
    bool initialized_ = false;
};

} // namespace rbw::view
