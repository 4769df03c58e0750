#include "app/gui/panels/view/scene_view.h"

#include "app/gui/style/number_text.h"

#include "app/gui/panels/view/ray_pick.h"
#include "app/gui/panels/view/view_style.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QPainterPath>
#include <QSurfaceFormat>
#include <QWheelEvent>
#include <QtDebug>

#include <cmath>

namespace rbw {

namespace {

constexpr size_t kMaxTrailPoints = 4000;

QColor toQColor(view::Rgba c) { return QColor::fromRgbF(c.r, c.g, c.b, c.a); }

QVector3D toQt(const Vec3& v) { return QVector3D(float(v.x()), float(v.y()), float(v.z())); }

// A magnitude for the legend, 3 significant digits.
QString magnitude(double value, const char* unit)
{
    return QStringLiteral("%1 %2").arg(QString::number(value, 'g', 3), QString::fromUtf8(unit));
}

} // namespace

SceneView::SceneView(QWidget* parent)
    : QOpenGLWidget(parent)
{
    setFormat(requestedFormat());
    setFocusPolicy(Qt::ClickFocus);
    setMouseTracking(false);
    glError_ = tr("OpenGL is not initialised yet.");
    setToolTip(tr("Left-drag: orbit, or drag a box · Alt+left-drag: orbit · right/middle-drag: pan · wheel: zoom\n"
                  "F: frame the bodies · Home: reset the view\n"
                  "Arrow lengths: the longest arrow of each kind is drawn one box long (see the legend)."));
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

    // clip = P V p
    const Eigen::Matrix4d PV = camera_.projectionMatrix(aspect()) * camera_.viewMatrix();
    renderer_.draw(geometry, PV, camera_.forward(), camera_.right(), camera_.up());

    painter.begin(this);
    painter.setRenderHint(QPainter::Antialiasing);
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
    QString text = tr("step %1 · t = %2 s · h = %3 s · %4")
                       .arg(snapshot_.nextStep)
                       .arg(shortNumber(snapshot_.time))
                       .arg(shortNumber(snapshot_.h))   // as the h box shows it
                       .arg(QString::fromStdString(snapshot_.integrator));
    if (snapshot_.energyFinite) text += tr(" · E = %1 J").arg(snapshot_.energy, 0, 'g', 7);
    if (followBody_ >= 0 && followBody_ < static_cast<int>(snapshot_.bodies.size())) {
        text += tr(" · following %1").arg(QString::fromStdString(snapshot_.bodies[static_cast<size_t>(followBody_)].name));
    }
    return text;
}

void SceneView::paintInfo(QPainter& painter) const
{
    if (!hasSnapshot_) return;
    QFont font = painter.font();
    font.setPointSizeF(9.0);
    painter.setFont(font);
    const QFontMetrics fm(font);
    const QString text = infoText();
    const QRect box(8, 8, fm.horizontalAdvance(text) + 16, fm.height() + 10);
    painter.setPen(QColor(0, 0, 0, 40));
    painter.setBrush(QColor(255, 255, 255, 215));
    painter.drawRoundedRect(box, 6, 6);
    painter.setPen(QColor(30, 30, 35));
    painter.drawText(box, Qt::AlignCenter, text);
}

void SceneView::paintGlError(QPainter& painter) const
{
    painter.fillRect(rect(), QColor(235, 238, 242));
    painter.setPen(QColor(120, 20, 20));
    painter.drawText(rect().adjusted(16, 16, -16, -16), Qt::AlignCenter | Qt::TextWordWrap, glError_);
}

void SceneView::paintLegend(QPainter& painter) const
{
    const view::ArrowScales& s = scales_;
    struct Row {
        view::Rgba colour;
        QString text;
    };
    std::vector<Row> rows;
    const QString box = tr("1 box = %1").arg(magnitude(s.refLength, "m"));
    if (s.hasApplied) rows.push_back({view::kForce, tr("force fᵢ at pᵢ, acts in step %1").arg(snapshot_.nextStep)});
    if (s.hasAppliedDone) rows.push_back({view::kForceDone, tr("force fᵢ of the step just taken (faded)")});
    if (s.hasGravity) rows.push_back({view::kGravity, tr("gravity M·g, ending at x")});
    if (s.hasApplied || s.hasAppliedDone || s.hasGravity) {
        rows.back().text += tr("  (longest %1)").arg(magnitude(s.maxForce, "N"));
    }
    if (s.hasProbes) rows.push_back({view::kProbe, tr("probe p, velocity v_p  (longest %1)").arg(magnitude(s.maxVelocity, "m/s"))});
    if (s.hasContacts) {
        rows.push_back({view::kContact, tr("contact p, normal n into A  (unit, ½ box)")});
        rows.push_back({view::kImpulse, s.maxImpulse > 0.0 ? tr("impulse J·n on A, ending at p  (longest %1)").arg(magnitude(s.maxImpulse, "N·s"))
                                                            : tr("impulse J·n on A  (none: separating)")});
        if (s.hasFriction) {
            rows.push_back({view::kFriction, tr("friction impulse Jₜ·t on A, ending at p")});
            rows.push_back({view::kTotalImpulse, tr("total impulse J·n + Jₜ·t on A")});
        }
    }
    if (s.hasVelocity) rows.push_back({view::kVelocity, tr("velocity v at x  (longest %1)").arg(magnitude(s.maxBodyVelocity, "m/s"))});
    if (s.hasOmega) rows.push_back({view::kOmega, tr("angular velocity ω at x  (longest %1)").arg(magnitude(s.maxOmega, "rad/s"))});
    if (s.hasL) rows.push_back({view::kAngularMomentum, tr("angular momentum L at x  (longest %1)").arg(magnitude(s.maxL, "N·m·s"))});
    if (s.hasSpring) rows.push_back({view::kSpring, tr("drag spring")});

    QFont font = painter.font();
    font.setPointSizeF(8.5);
    painter.setFont(font);
    const QFontMetrics fm(font);
    const int line = fm.height() + 2;
    const int swatch = 18;
    int textWidth = fm.horizontalAdvance(tr("axes x y z (body frame)"));
    for (const Row& r : rows) textWidth = std::max(textWidth, fm.horizontalAdvance(r.text));
    const QString header = rows.size() > 0 ? tr("Arrows: longest of each kind = 1 box (%1)").arg(box) : QString();
    textWidth = std::max(textWidth, fm.horizontalAdvance(header) - swatch - 6);
    const int lineCount = int(rows.size()) + 1 + (header.isEmpty() ? 0 : 1);
    const QRect panel(8, height() - 8 - lineCount * line - 10, textWidth + swatch + 22, lineCount * line + 10);

    painter.setPen(QColor(0, 0, 0, 40));
    painter.setBrush(QColor(255, 255, 255, 215));
    painter.drawRoundedRect(panel, 6, 6);
    int y = panel.top() + 5;
    auto drawRow = [&](const QString& text) {
        painter.setPen(QColor(30, 30, 35));
        painter.drawText(QRect(panel.left() + swatch + 14, y, textWidth + 4, line), Qt::AlignVCenter | Qt::AlignLeft, text);
    };
    if (!header.isEmpty()) {
        painter.setPen(QColor(60, 60, 70));
        painter.drawText(QRect(panel.left() + 8, y, panel.width() - 12, line), Qt::AlignVCenter | Qt::AlignLeft, header);
        y += line;
    }
    for (const Row& r : rows) {
        const int cy = y + line / 2;
        painter.setPen(QPen(toQColor(r.colour), 3, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(panel.left() + 8, cy, panel.left() + 8 + swatch - 5, cy);
        // A small arrow head on the swatch.
        QPainterPath head;
        head.moveTo(panel.left() + 8 + swatch, cy);
        head.lineTo(panel.left() + 8 + swatch - 6, cy - 4);
        head.lineTo(panel.left() + 8 + swatch - 6, cy + 4);
        head.closeSubpath();
        painter.fillPath(head, toQColor(r.colour));
        drawRow(r.text);
        y += line;
    }
    // Body axes: three short coloured strokes.
    const int cy = y + line / 2;
    const view::Rgba axes[3] = {view::kAxisX, view::kAxisY, view::kAxisZ};
    for (int j = 0; j < 3; ++j) {
        painter.setPen(QPen(toQColor(axes[j]), 2));
        painter.drawLine(panel.left() + 8 + 6 * j, cy + 5, panel.left() + 8 + 6 * j + 3, cy - 5);
    }
    drawRow(tr("axes x y z (body frame)"));
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
    trailsVisible_ = visible;
    update();
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
    case DragMode::None:
        break;
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
    } else {
        QOpenGLWidget::keyPressEvent(event);
    }
}

} // namespace rbw
