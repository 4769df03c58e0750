#include "app/gui/panels/view/scene_view.h"

#include "app/core/step_numbering.h"
#include "app/output/atomic_file.h"
#include "physics/engine/integrator_registry.h"

#include "app/gui/style/number_text.h"

#include "app/gui/panels/view/ray_pick.h"
#include "app/gui/panels/view/view_style.h"

#include <QAction>
#include <QBuffer>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QStandardPaths>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QSurfaceFormat>
#include <QWheelEvent>
#include <QtDebug>

#include <cmath>

namespace rbw {

namespace {

constexpr size_t kMaxTrailPoints = 4000;

QVector3D toQt(const Vec3& v) { return QVector3D(float(v.x()), float(v.y()), float(v.z())); }

} // namespace

SceneView::SceneView(QWidget* parent)
    : QOpenGLWidget(parent)
{
    setFormat(requestedFormat());
    setFocusPolicy(Qt::ClickFocus);
    setMouseTracking(true);   // hovering names the body under the mouse
    glError_ = tr("OpenGL is not initialised yet.");
    createViewActions();
    setToolTip(tr("Left-drag: orbit, or drag a box · Alt+left-drag: orbit · right/middle-drag: pan · wheel: zoom\n"
                  "F: frame the bodies · Home: reset the view · 1/2/3: front/top/side view · N: body names\n"
                  "Arrow lengths: the longest arrow of each kind is drawn one box long (see the legend)."));
}

void SceneView::createViewActions()
{
    const struct {
        QString text;
        const char* name;
        Qt::Key key;
        StandardView view;
    } views[] = {{tr("&Front view (seen from +z: x right, y up)"), "actionFrontView", Qt::Key_1, StandardView::Front},
                 {tr("&Top view (seen from +y: x right, −z up)"), "actionTopView", Qt::Key_2, StandardView::Top},
                 {tr("&Side view (seen from +x: −z right, y up)"), "actionSideView", Qt::Key_3, StandardView::Side}};
    for (const auto& v : views) {
        auto* a = new QAction(v.text, this);
        a->setObjectName(QString::fromLatin1(v.name));
        a->setShortcut(QKeySequence(v.key));
        const StandardView which = v.view;
        connect(a, &QAction::triggered, this, [this, which] { setStandardView(which); });
        viewActions_.push_back(a);
    }
    auto* names = new QAction(tr("Body &names"), this);
    names->setObjectName("actionBodyNames");
    names->setShortcut(QKeySequence(Qt::Key_N));
    names->setCheckable(true);
    connect(names, &QAction::toggled, this, &SceneView::setBodyNamesVisible);
    viewActions_.push_back(names);
    auto* save = new QAction(tr("Save the view as &PNG…"), this);
    save->setObjectName("actionSaveViewPng");
    save->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_P));
    connect(save, &QAction::triggered, this, &SceneView::saveImageAsked);
    viewActions_.push_back(save);
    addActions(viewActions_);
}

bool SceneView::saveImage(const QString& path, QString* error)
{
    const QImage image = grabFramebuffer();   // the view as the student sees it, overlays included
    if (image.isNull()) {
        if (error != nullptr) *error = tr("%1: cannot write: the view has no picture yet").arg(path);
        return false;
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) {
        if (error != nullptr) *error = tr("%1: cannot write: the picture cannot be encoded as PNG").arg(path);
        return false;
    }
    return writeFileAtomically(path, bytes, error);
}

void SceneView::saveImageAsked()
{
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::PicturesLocation);
    const QString path = QFileDialog::getSaveFileName(this, tr("Save the view as PNG"), folder + QStringLiteral("/view.png"),
                                                      tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    QString error;
    if (!saveImage(path, &error)) QMessageBox::warning(this, tr("Save the view as PNG"), error);
}

QAction* SceneView::viewActionFor(const QKeyEvent* event) const
{
    if (event->modifiers() != Qt::NoModifier && event->modifiers() != Qt::KeypadModifier) return nullptr;
    for (QAction* a : viewActions_) {
        if (a->shortcut() == QKeySequence(event->key())) return a;
    }
    return nullptr;
}

SceneView::~SceneView()
{
    releaseGl();
}

QSurfaceFormat SceneView::requestedFormat()
{
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    // No multisampling: on a software rasteriser (Mesa llvmpipe) 4x MSAA costs about
    // three times the frame time (and GL_LINE_SMOOTH draws broken, light lines there).
    format.setSamples(0);
    return format;
}

void SceneView::releaseGl()
{
    if (!renderer_.isInitialized() || context() == nullptr) return;
    makeCurrent();
    renderer_.release();
    doneCurrent();
}

void SceneView::initializeGL()
{
    glReady_ = false;
    QOpenGLContext* ctx = context();
    if (ctx == nullptr || !ctx->isValid()) {
        glError_ = tr("No OpenGL context could be created; the 3D view is off.");
        qWarning("rbw::SceneView: %s", qPrintable(glError_));
        return;
    }
    connect(ctx, &QOpenGLContext::aboutToBeDestroyed, this, &SceneView::releaseGl, Qt::UniqueConnection);
    const QSurfaceFormat f = ctx->format();
    QOpenGLFunctions* gl = ctx->functions();
    const auto* version = reinterpret_cast<const char*>(gl->glGetString(GL_VERSION));
    const auto* rendererName = reinterpret_cast<const char*>(gl->glGetString(GL_RENDERER));
    glVersion_ = QStringLiteral("OpenGL %1.%2 %3 (%4, %5)")
                     .arg(f.majorVersion())
                     .arg(f.minorVersion())
                     .arg(f.profile() == QSurfaceFormat::CoreProfile ? QStringLiteral("core")
                                                                       : QStringLiteral("compatibility"))
                     .arg(QString::fromLatin1(version ? version : "?"), QString::fromLatin1(rendererName ? rendererName : "?"));
    if (ctx->isOpenGLES() || f.version() < qMakePair(3, 3)) {
        glError_ = tr("The 3D view needs OpenGL 3.3; this system offers %1.").arg(glVersion_);
        qWarning("rbw::SceneView: %s", qPrintable(glError_));
        return;
    }
    QString error;
    if (!renderer_.initialize(&error)) {
        glError_ = tr("The 3D view cannot start: %1").arg(error);
        qWarning("rbw::SceneView: %s", qPrintable(glError_));
        return;
    }
    glReady_ = true;
    glError_.clear();
}

double SceneView::aspect() const
{
    return height() > 0 ? double(width()) / double(height()) : 1.0;
}

void SceneView::paintGL()
{
    ++framesRendered_;
    QPainter painter;
    if (!glReady_) {
        painter.begin(this);
        paintGlError(painter);
        return;
    }
    const view::FrameGeometry geometry = buildFrameGeometry(snapshot_, trails_, frameOptions());
    scales_ = geometry.scales;
    arrows_ = geometry.arrows;
    world_ = geometry.world;
    labels_ = geometry.labels;

    // clip = P V p
    const Eigen::Matrix4d PV = camera_.projectionMatrix(aspect()) * camera_.viewMatrix();
    renderer_.draw(geometry, PV, camera_.forward(), camera_.right(), camera_.up());

    painter.begin(this);
    painter.setRenderHint(QPainter::Antialiasing);
    paintLabels(painter);
    paintLegend(painter);
    paintInfo(painter);
}

view::FrameOptions SceneView::frameOptions() const
{
    view::FrameOptions options;
    options.eye_W = camera_.eye();
    options.sceneBox = sceneBox_;
    options.trails = trailsVisible_;
    options.highlightBody = drag_ == DragMode::Grab ? grabBody_ : -1;
    options.velocity = showVelocity_;
    options.angularVelocity = showOmega_;
    options.angularMomentum = showL_;
    return options;
}

std::vector<view::ArrowRecord> SceneView::currentArrows() const
{
    return buildFrameGeometry(snapshot_, trails_, frameOptions()).arrows;
}

void SceneView::setShowVelocity(bool on)
{
    showVelocity_ = on;
    update();
}

void SceneView::setShowAngularVelocity(bool on)
{
    showOmega_ = on;
    update();
}

void SceneView::setShowAngularMomentum(bool on)
{
    showL_ = on;
    update();
}

void SceneView::setFollowBody(int body)
{
    followBody_ = (body >= 0 && body < static_cast<int>(snapshot_.bodies.size())) ? body : -1;
    follow();
    update();
}

void SceneView::follow()
{
    if (followBody_ < 0 || followBody_ >= static_cast<int>(snapshot_.bodies.size())) return;
    const ViewSnapshot::Body& b = snapshot_.bodies[static_cast<size_t>(followBody_)];
    if (b.finite) camera_.setTarget(b.x_W);
}

QString SceneView::infoText() const
{
    // One step numbering everywhere (app/core/step_numbering.h): the line names the
    // step just taken and the time it led to, "after step k = 2 · t₃ = 0.05 s".
    const QString step = steps::stateName(snapshot_.nextStep);
    const IntegratorInfo* integrator = findIntegrator(snapshot_.integrator);
    const QString method = integrator != nullptr && *integrator->title != '\0' ? QString::fromUtf8(integrator->title)
                                                                               : QString::fromStdString(snapshot_.integrator);
    QString text = tr("%1 · %2 = %3 s · h = %4 s · %5")
                       .arg(step, steps::timeName(snapshot_.nextStep))
                       .arg(shortNumber(snapshot_.time))
                       .arg(shortNumber(snapshot_.h))   // as the h box shows it
                       .arg(method);
    if (snapshot_.energyFinite) text += tr(" · E = %1 J").arg(snapshot_.energy, 0, 'g', 7);
    if (followBody_ >= 0 && followBody_ < static_cast<int>(snapshot_.bodies.size())) {
        text += tr(" · following %1").arg(QString::fromStdString(snapshot_.bodies[static_cast<size_t>(followBody_)].name));
    }
    return text;
}

bool SceneView::sameScene(const ViewSnapshot& other) const
{
    if (!hasSnapshot_ || other.bodies.size() != snapshot_.bodies.size() ||
        other.planes.size() != snapshot_.planes.size()) {
        return false;
    }
    for (size_t b = 0; b < other.bodies.size(); ++b) {
        if (other.bodies[b].name != snapshot_.bodies[b].name || other.bodies[b].size != snapshot_.bodies[b].size) {
            return false;
        }
    }
    for (size_t p = 0; p < other.planes.size(); ++p) {
        if (other.planes[p].point_W != snapshot_.planes[p].point_W || other.planes[p].n_W != snapshot_.planes[p].n_W) {
            return false;
        }
    }
    return true;
}

void SceneView::updateSceneBox()
{
    // Bodies (as far as they have been) and the planes' points, plus a margin.
    view::Bounds box = view::bodyBounds(snapshot_);
    for (const ViewSnapshot::Plane& p : snapshot_.planes) box.add(p.point_W);
    if (!box.valid()) return;
    const double margin = std::max(1.0, 0.25 * (box.max_W - box.min_W).norm());
    box.min_W -= Vec3::Constant(margin);
    box.max_W += Vec3::Constant(margin);
    sceneBox_.add(box);
}

void SceneView::setSnapshot(const ViewSnapshot& snapshot)
{
    const bool newScene = !sameScene(snapshot);
    const bool wentBack = hasSnapshot_ && snapshot.time < snapshot_.time;
    snapshot_ = snapshot;
    hasSnapshot_ = true;
    if (newScene) {
        followBody_ = -1;
        sceneBox_ = view::Bounds{};
        clearTrails();
        resetView();
        // Trails where they help: off for more than kMaxTrailedBodies (lesson 4's pen of
        // six tumbling boxes and its fifty, where they tangle into a knot).
        setTrailsVisible(static_cast<int>(snapshot_.bodies.size()) <= kMaxTrailedBodies);
    } else if (wentBack) {
        clearTrails();
    }
    updateSceneBox();
    follow();

    // Trails: append each centre of mass when it moved visibly.
    trails_.resize(snapshot_.bodies.size());
    const double minStep = 1e-3 * view::referenceLength(snapshot_);
    for (size_t b = 0; b < snapshot_.bodies.size(); ++b) {
        const ViewSnapshot::Body& body = snapshot_.bodies[b];
        if (!body.finite || body.fixed) continue;
        std::vector<Vec3>& trail = trails_[b];
        if (trail.empty() || (trail.back() - body.x_W).norm() > minStep) trail.push_back(body.x_W);
        if (trail.size() > kMaxTrailPoints) trail.erase(trail.begin(), trail.begin() + kMaxTrailPoints / 2);
    }
    update();
}

void SceneView::setSpring(std::optional<std::pair<Vec3, Vec3>> fromTo_W)
{
    if (fromTo_W && isFinite(fromTo_W->first) && isFinite(fromTo_W->second)) {
        snapshot_.spring = ViewSnapshot::Spring{grabBody_, fromTo_W->first, fromTo_W->second};
    } else {
        snapshot_.spring.reset();
    }
    update();
}

void SceneView::clearTrails()
{
    trails_.assign(snapshot_.bodies.size(), {});
    update();
}

void SceneView::setTrailsVisible(bool visible)
{
    const bool changed = visible != trailsVisible_;
    trailsVisible_ = visible;
    if (changed) emit trailsVisibleChanged(visible);
    update();
}

void SceneView::setStandardView(StandardView v)
{
    camera_.setStandardView(v);
    fitToScene();
}

void SceneView::setBodyNamesVisible(bool on)
{
    bodyNamesVisible_ = on;
    update();
}

void SceneView::setHoveredBody(int body)
{
    if (body == hoveredBody_) return;
    hoveredBody_ = body;
    update();
}

void SceneView::leaveEvent(QEvent* event)
{
    setHoveredBody(-1);
    QOpenGLWidget::leaveEvent(event);
}

void SceneView::resetView()
{
    camera_.setAngles(OrbitCamera::kDefaultYawDeg, OrbitCamera::kDefaultPitchDeg);
    fitToScene();
}

void SceneView::fitToScene()
{
    const view::Bounds b = view::bodyBounds(snapshot_);
    if (b.valid()) {
        // The bounding sphere of the bodies' box, widened by one reference
        // lengths so that arrows (up to one box long) starting at corners and probes
        // off the bodies stay in view.
        const double radius = 0.5 * (b.max_W - b.min_W).norm() + 1.0 * view::referenceLength(snapshot_);
        camera_.frame(0.5 * (b.min_W + b.max_W), radius, aspect());
    } else {
        camera_.frame(Vec3::Zero(), 1.0, aspect());
    }
    update();
}

void SceneView::orbitBy(double dxPx, double dyPx)
{
    camera_.orbit(dxPx, dyPx);
    update();
}

void SceneView::panBy(double dxPx, double dyPx)
{
    camera_.pan(dxPx, dyPx, height());
    update();
}

void SceneView::zoomBy(double wheelSteps)
{
    camera_.zoom(wheelSteps);
    update();
}

Ray SceneView::rayAt(const QPointF& widgetPos) const
{
    // Widget pixels -> ndc: x from [0, w] to [-1, 1], y flipped.
    const double w = std::max(1, width());
    const double h = std::max(1, height());
    return camera_.rayThroughNdc(2.0 * widgetPos.x() / w - 1.0, 1.0 - 2.0 * widgetPos.y() / h, aspect());
}

std::optional<SceneView::Pick> SceneView::pick(QPoint widgetPos) const
{
    const std::optional<BoxHit> hit = pickBody(rayAt(QPointF(widgetPos) + QPointF(0.5, 0.5)), snapshot_);
    if (!hit) return std::nullopt;
    return Pick{hit->body, hit->hit_W};
}

QPointF SceneView::projectToWidget(const Vec3& p_W) const
{
    // clip = P V [p; 1], ndc = clip.xyz / clip.w, then ndc -> widget pixels.
    const Eigen::Vector4d clip =
        camera_.projectionMatrix(aspect()) * (camera_.viewMatrix() * Eigen::Vector4d(p_W.x(), p_W.y(), p_W.z(), 1.0));
    if (!(clip.w() > 1e-12) || !clip.allFinite()) return QPointF(-1.0, -1.0);
    const double ndcX = clip.x() / clip.w();
    const double ndcY = clip.y() / clip.w();
    return QPointF(0.5 * (ndcX + 1.0) * width(), 0.5 * (1.0 - ndcY) * height());
}

void SceneView::mousePressEvent(QMouseEvent* event)
{
    lastMouse_ = event->position();
    const bool alt = event->modifiers().testFlag(Qt::AltModifier);
    if (event->button() == Qt::LeftButton && !alt) {
        const std::optional<Pick> hit = pick(event->position().toPoint());
        if (hit && !snapshot_.bodies[hit->body].fixed) {
            // The drag plane: through the hit point, perpendicular to the view direction.
            drag_ = DragMode::Grab;
            grabBody_ = hit->body;
            grabPoint_W_ = hit->hit_W;
            grabNormal_W_ = camera_.forward();
            emit grabStarted(grabBody_, toQt(hit->hit_W));
            update();
            event->accept();
            return;
        }
        drag_ = DragMode::Orbit;
    } else if (event->button() == Qt::LeftButton) {
        drag_ = DragMode::Orbit;
    } else if (event->button() == Qt::RightButton || event->button() == Qt::MiddleButton) {
        drag_ = DragMode::Pan;
    }
    pressPos_ = event->position();
    event->accept();
}

void SceneView::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF delta = event->position() - lastMouse_;
    lastMouse_ = event->position();
    switch (drag_) {
    case DragMode::Orbit:
        orbitBy(delta.x(), delta.y());
        break;
    case DragMode::Pan:
        panBy(delta.x(), delta.y());
        break;
    case DragMode::Grab: {
        const Ray ray = rayAt(event->position());
        if (const std::optional<double> t = rayPlaneHit(ray, grabPoint_W_, grabNormal_W_)) {
            emit grabMoved(toQt(ray.origin_W + *t * ray.dir_W));
        }
        break;
    }
    case DragMode::None: {
        // Hovering: name the body under the mouse.
        hoverPos_ = event->position();
        const std::optional<Pick> hit = pick(event->position().toPoint());
        setHoveredBody(hit ? hit->body : -1);
        if (hit) update();   // the name follows the mouse
        break;
    }
    }
    event->accept();
}

void SceneView::mouseReleaseEvent(QMouseEvent* event)
{
    if (drag_ == DragMode::Grab) {
        drag_ = DragMode::None;
        grabBody_ = -1;
        emit grabEnded();
        update();
    }
    drag_ = DragMode::None;
    // A right click that did not pan: the view's menu (views, names, Save as PNG).
    if (event->button() == Qt::RightButton && (event->position() - pressPos_).manhattanLength() < 4) {
        QMenu menu(this);
        menu.addActions(viewActions_);
        menu.exec(event->globalPosition().toPoint());
    }
    event->accept();
}

void SceneView::wheelEvent(QWheelEvent* event)
{
    // One notch = 120 eighths of a degree.
    zoomBy(event->angleDelta().y() / 120.0);
    event->accept();
}

void SceneView::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_F && event->modifiers() == Qt::NoModifier) {
        fitToScene();
    } else if (event->key() == Qt::Key_Home) {
        resetView();
    } else if (QAction* a = viewActionFor(event)) {
        a->trigger();   // the keys of the view's actions, when no window shortcut took them
    } else {
        QOpenGLWidget::keyPressEvent(event);
    }
}

} // namespace rbw
