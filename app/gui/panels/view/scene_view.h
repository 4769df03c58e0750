// The 3D view: a QOpenGLWidget (OpenGL 3.3 core) that draws a ViewSnapshot, the
// world and the arrows of the current step, and lets the student orbit, pan, zoom,
// pick and drag a body. It never steps or recomputes physics: it draws what the
// snapshot (built from the world and the trace) holds, and turns a drag into
// signals; the main window applies the spring force and passes the spring back.
//
// Mouse: left-drag on empty space (or Alt+left-drag anywhere) orbits; right- or
// middle-drag pans; the wheel zooms; left-press on a movable box grabs it.
// Keys: F frames the bodies, Home resets the view; 1, 2, 3 the front (seen from +z),
// top (from +y) and side (from +x) views (see StandardView in orbit_camera.h); N
// writes each body's name beside it. Hovering over a body names it.
#pragma once

#include "app/gui/panels/view/frame_geometry.h"
#include "app/gui/panels/view/orbit_camera.h"
#include "app/gui/panels/view/scene_renderer.h"
#include "app/gui/panels/view/view_snapshot.h"

#include <QFontMetrics>
#include <QList>
#include <QStringList>
#include <QOpenGLWidget>
#include <QPointF>
#include <QString>
#include <QVector3D>

#include <optional>
#include <utility>
#include <vector>

namespace rbw {

class SceneView : public QOpenGLWidget {
    Q_OBJECT
public:
    // The body under a pixel and where the ray from the eye first enters it.
    struct Pick {
        int body = -1;
        Vec3 hit_W = Vec3::Zero();
    };

    explicit SceneView(QWidget* parent = nullptr);
    ~SceneView() override;

    // The format the view asks for: OpenGL 3.3 core, 24-bit depth, no multisampling.
    static QSurfaceFormat requestedFormat();

    // Shows a new state. Appends each body's x_W to its trail; a snapshot of another
    // scene (other bodies or planes) clears the trails and frames the new scene, and
    // one that goes back in time (a reset) clears the trails.
    void setSnapshot(const ViewSnapshot& snapshot);
    const ViewSnapshot& snapshot() const { return snapshot_; }

    // The drag spring (picked point, target), drawn as a line; nullopt hides it.
    void setSpring(std::optional<std::pair<Vec3, Vec3>> fromTo_W);

    void clearTrails();
    // Trails are shown by default in a scene of at most kMaxTrailedBodies bodies; each
    // new scene sets that default again (trailsVisibleChanged tells the View menu).
    static constexpr int kMaxTrailedBodies = 5;
    void setTrailsVisible(bool visible);
    bool trailsVisible() const { return trailsVisible_; }
    const std::vector<std::vector<Vec3>>& trails() const { return trails_; }

    // Camera. resetView: the default angles (slightly above the scene), framing the bodies.
    void resetView();
    void fitToScene();   // frames all bodies, keeps the angles; infinite planes are ignored
    const OrbitCamera& camera() const { return camera_; }
    void orbitBy(double dxPx, double dyPx);
    void panBy(double dxPx, double dyPx);
    void zoomBy(double wheelSteps);
    // A standard view (front, top, side), framing the bodies.
    void setStandardView(StandardView v);

    // The view's own actions, for the View menu: Front (1), Top (2), Side (3) view,
    // and Body names (N, checkable). They are added to the view too, so their keys
    // work wherever the view's window is active.
    QList<QAction*> viewActions() const { return viewActions_; }

    // Body names: always on hover; written beside every body when this is on.
    void setBodyNamesVisible(bool on);
    bool bodyNamesVisible() const { return bodyNamesVisible_; }
    int hoveredBody() const { return hoveredBody_; }   // -1 when the mouse is over no body
    // The world reference (axes at the origin, ground grid) and the axis labels of
    // the last frame (for the tests).
    const view::WorldReference& worldReference() const { return world_; }
    const std::vector<view::SceneLabel>& labels() const { return labels_; }

    // Picking and projection in widget (logical) pixels.
    std::optional<Pick> pick(QPoint widgetPos) const;   // through the centre of that pixel
    Ray rayAt(const QPointF& widgetPos) const;
    // Where a world point appears; a point behind the camera maps to (-1, -1).
    QPointF projectToWidget(const Vec3& p_W) const;

    // The view as it is on screen (3D, overlays, legend) as a PNG file, through the
    // atomic writer; false and *error ("PATH: cannot write: REASON") if not written.
    // The action "Save the view as PNG…" (View menu, the view's right-click menu) asks
    // for the file.
    bool saveImage(const QString& path, QString* error = nullptr);

    // For fps measurements and diagnostics.
    int framesRendered() const { return framesRendered_; }
    QString glVersionString() const { return glVersion_; }
    bool isGlReady() const { return glReady_; }
    QString glError() const { return glError_; }   // why nothing is drawn, empty if fine

    // What the arrows of the last frame are scaled to (see frame_geometry.h), and the
    // arrows themselves (what each shows, from where to where).
    const view::ArrowScales& arrowScales() const { return scales_; }
    const std::vector<view::ArrowRecord>& arrows() const { return arrows_; }
    // The same arrows as the next frame draws them, without drawing (tests, no GL needed).
    std::vector<view::ArrowRecord> currentArrows() const;

    // The state arrows at each body's centre: v, ω and L (View menu).
    void setShowVelocity(bool on);
    void setShowAngularVelocity(bool on);
    void setShowAngularMomentum(bool on);
    bool showsVelocity() const { return showVelocity_; }
    bool showsAngularVelocity() const { return showOmega_; }
    bool showsAngularMomentum() const { return showL_; }

    // The camera follows body b (its centre stays the orbit target as it moves); -1
    // stops following. A body that is not finite is not followed.
    void setFollowBody(int body);
    int followBody() const { return followBody_; }

    // The info overlay (top left): the step just taken (k counted from 0), t, h, the
    // integrator's name and the energy E, as one line.
    QString infoText() const;
    // That line as the overlay draws it: broken at its " · " into lines no wider than
    // maxWidth (a single part wider than that keeps its own line).
    static QStringList infoLines(const QString& text, const QFontMetrics& fm, int maxWidth);

    QSize sizeHint() const override { return {640, 480}; }
    QSize minimumSizeHint() const override { return {160, 120}; }

signals:
    void trailsVisibleChanged(bool visible);
    void grabStarted(int body, QVector3D hit_W);
    void grabMoved(QVector3D target_W);   // on the plane through the hit point, facing the camera
    void grabEnded();

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    enum class DragMode { None, Orbit, Pan, Grab };

    double aspect() const;
    void releaseGl();
    void paintLegend(QPainter& painter) const;
    void paintInfo(QPainter& painter) const;
    void paintLabels(QPainter& painter) const;
    void createViewActions();
    void saveImageAsked();
    QAction* viewActionFor(const QKeyEvent* event) const;
    void setHoveredBody(int body);
    view::FrameOptions frameOptions() const;
    void follow();
    void paintGlError(QPainter& painter) const;
    bool sameScene(const ViewSnapshot& other) const;
    void updateSceneBox();

    ViewSnapshot snapshot_;
    bool hasSnapshot_ = false;
    std::vector<std::vector<Vec3>> trails_;
    bool trailsVisible_ = true;
    view::Bounds sceneBox_;   // grows with the bodies; where plane patches end

    OrbitCamera camera_;
    DragMode drag_ = DragMode::None;
    QPointF lastMouse_;
    int grabBody_ = -1;
    Vec3 grabPoint_W_ = Vec3::Zero();   // a point on the drag plane
    Vec3 grabNormal_W_ = Vec3::UnitZ();   // the drag plane's normal (the view direction at grab time)

    view::SceneRenderer renderer_;
    view::ArrowScales scales_;
    std::vector<view::ArrowRecord> arrows_;
    bool showVelocity_ = false;
    bool showOmega_ = false;
    bool showL_ = false;
    int followBody_ = -1;
    QList<QAction*> viewActions_;
    bool bodyNamesVisible_ = false;
    int hoveredBody_ = -1;
    QPointF hoverPos_;
    QPointF pressPos_;   // where the last button went down (a right click without a pan opens the menu)
    view::WorldReference world_;
    std::vector<view::SceneLabel> labels_;
    bool glReady_ = false;
    QString glError_;
    QString glVersion_;
    int framesRendered_ = 0;
};

} // namespace rbw
