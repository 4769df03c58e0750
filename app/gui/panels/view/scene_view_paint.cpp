// The 3D view's 2D overlay, painted with QPainter over the GL frame: the axis
// labels and body names, the legend (what each arrow and line stands for), the info
// line and the message shown when OpenGL is not available.
#include "app/gui/panels/view/scene_view.h"

#include "app/gui/panels/view/view_style.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace rbw {

namespace {

QColor toQColor(view::Rgba c) { return QColor::fromRgbF(c.r, c.g, c.b, c.a); }

// A magnitude for the legend, 3 significant digits.
QString magnitude(double value, const char* unit)
{
    return QStringLiteral("%1 %2").arg(QString::number(value, 'g', 3), QString::fromUtf8(unit));
}

} // namespace

void SceneView::paintLabels(QPainter& painter) const
{
    QFont font = painter.font();
    font.setPointSizeF(9.5);
    font.setBold(true);
    painter.setFont(font);
    const QFontMetrics fm(font);
    const view::Rgba axisColour[3] = {view::kAxisX, view::kAxisY, view::kAxisZ};
    auto label = [&](const QPointF& at, const QString& text, QColor colour, bool boxed, const QFontMetrics& m) {
        if (at.x() < 0.0 && at.y() < 0.0) return;   // behind the camera
        const QRectF box(at.x() - m.horizontalAdvance(text) / 2.0 - 3, at.y() - m.height() / 2.0 - 1,
                         m.horizontalAdvance(text) + 6, m.height() + 2);
        if (boxed) {
            painter.setPen(QColor(0, 0, 0, 60));
            painter.setBrush(QColor(255, 255, 255, 225));
            painter.drawRoundedRect(box, 4, 4);
        }
        painter.setPen(colour);
        painter.drawText(box, Qt::AlignCenter, text);
    };
    for (const view::SceneLabel& l : labels_) {
        label(projectToWidget(l.at_W), QString::fromStdString(l.text), toQColor(axisColour[l.axis]), false, fm);
    }
    // Body names: every body when switched on, else the one under the mouse; in a
    // lighter, smaller font than the axis letters, so that neighbours' names overlap less.
    QFont nameFont = font;
    nameFont.setBold(false);
    nameFont.setPointSizeF(8.5);
    const QFontMetrics nameMetrics(nameFont);
    for (int b = 0; b < static_cast<int>(snapshot_.bodies.size()); ++b) {
        const ViewSnapshot::Body& body = snapshot_.bodies[static_cast<size_t>(b)];
        if (!body.finite || !(bodyNamesVisible_ || b == hoveredBody_)) continue;
        // Above the body's top: its centre raised by half its world height.
        const Vec3 top_W = body.x_W + Vec3(0.0, (body.R_WB.cwiseAbs() * (0.5 * body.size)).y(), 0.0);
        QPointF at = projectToWidget(top_W) - QPointF(0.0, fm.height());
        if (b == hoveredBody_ && !bodyNamesVisible_) at = hoverPos_ + QPointF(0.0, -fm.height());
        painter.setFont(nameFont);
        label(at, QString::fromStdString(body.name), QColor(30, 30, 35), true, nameMetrics);
    }
}

QStringList SceneView::infoLines(const QString& text, const QFontMetrics& fm, int maxWidth)
{
    const QString separator = QStringLiteral(" · ");
    QStringList lines;
    QString line;
    for (const QString& part : text.split(separator)) {
        const QString longer = line.isEmpty() ? part : line + separator + part;
        if (!line.isEmpty() && fm.horizontalAdvance(longer) > maxWidth) {
            lines << line;
            line = part;
        } else {
            line = longer;
        }
    }
    if (!line.isEmpty()) lines << line;
    return lines;
}

void SceneView::paintInfo(QPainter& painter) const
{
    if (!hasSnapshot_) return;
    QFont font = painter.font();
    font.setPointSizeF(9.0);
    painter.setFont(font);
    const QFontMetrics fm(font);
    // Wrapped at its " · " where the view is narrower than the line (lesson 11 at
    // 1366x768 cut "E = 65.4199…" off): never clipped.
    const QStringList lines = infoLines(infoText(), fm, width() - 32);
    int widest = 0;
    for (const QString& line : lines) widest = std::max(widest, fm.horizontalAdvance(line));
    const QRect box(8, 8, widest + 16, fm.height() * static_cast<int>(lines.size()) + 10);
    painter.setPen(QColor(0, 0, 0, 40));
    painter.setBrush(QColor(255, 255, 255, 215));
    painter.drawRoundedRect(box, 6, 6);
    painter.setPen(QColor(30, 30, 35));
    painter.drawText(box.adjusted(8, 5, -8, -5), Qt::AlignLeft | Qt::AlignVCenter, lines.join('\n'));
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
    if (s.hasTorque) rows.push_back({view::kTorque, tr("torque qⱼ (a couple) at x, of the step just taken  (longest %1)").arg(magnitude(s.maxTorque, "N·m"))});
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
    if (trailsVisible_) {
        for (size_t b = 0; b < trails_.size() && b < snapshot_.bodies.size(); ++b) {
            if (trails_[b].size() < 2) continue;
            const ViewSnapshot::Body& body = snapshot_.bodies[b];
            const view::Rgba c = view::bodyColour(int(b), body.fixed, body.name);
            rows.push_back({view::Rgba{c.r + (1.f - c.r) * 0.25f, c.g + (1.f - c.g) * 0.25f, c.b + (1.f - c.b) * 0.25f, 1.f},
                            tr("trail: the path of each centre x  (T hides it)")});
            break;
        }
    }
    const QString worldRow = world_.shown ? tr("world axes at the origin · grid %1 at y = %2 m")
                                                .arg(magnitude(world_.spacing, "m"), QString::number(world_.y0, 'g', 3))
                                          : QString();

    QFont font = painter.font();
    font.setPointSizeF(8.5);
    painter.setFont(font);
    const QFontMetrics fm(font);
    const int line = fm.height() + 2;
    const int swatch = 18;
    int textWidth = std::max(fm.horizontalAdvance(tr("axes x y z (body frame)")), fm.horizontalAdvance(worldRow));
    for (const Row& r : rows) textWidth = std::max(textWidth, fm.horizontalAdvance(r.text));
    const QString header = rows.size() > 0 ? tr("Arrows: longest of each kind = 1 box (%1)").arg(box) : QString();
    textWidth = std::max(textWidth, fm.horizontalAdvance(header) - swatch - 6);
    const int lineCount = int(rows.size()) + 1 + (worldRow.isEmpty() ? 0 : 1) + (header.isEmpty() ? 0 : 1);
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
    if (!worldRow.isEmpty()) {
        y += line;
        const int cy = y + line / 2;
        painter.setPen(QPen(toQColor(view::kGrid), 1));
        for (int k = 0; k < 3; ++k) painter.drawLine(panel.left() + 8 + 6 * k, cy - 5, panel.left() + 8 + 6 * k, cy + 5);
        drawRow(worldRow);
    }
}

} // namespace rbw
