#include "app/gui/panels/derivation/derivation_session_panel.h"

#include "app/core/focus_filter.h"
#include "app/core/session.h"
#include "app/derivation/derivation_builder.h"
#include "app/gui/panels/derivation/derivation_view.h"

#include <QFileInfo>

namespace rbw {

namespace {

// The page shown before the first step: nothing is computed yet.
QString introPage(const Lesson& lesson)
{
    return QStringLiteral(
               "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><style>"
               "body{font-family:sans-serif;margin:1.5em;color:#222;background:#fcfcfa}"
               "h1{font-size:1.2em}p{line-height:1.5}</style></head><body>"
               "<h1>%1</h1><p>%2</p><p><b>Press Step (S or →)</b> to take the first step. This page then "
               "writes it out line by line: each formula, the formula with this step's numbers, "
               "and the result.</p></body></html>")
        .arg(lesson.title.toHtmlEscaped(), lesson.description.toHtmlEscaped());
}

} // namespace

bool DerivationSessionPanel::setFocusBody(int body)
{
    if (focusBody_ == body) return false;
    focusBody_ = body;
    return true;
}

void DerivationSessionPanel::refresh()
{
    if (!session_->isLoaded()) return;
    const StepTrace* trace = session_->currentTrace();
    const SceneDef& scene = session_->world()->scene();
    const Lesson& lesson = lesson_();
    if (trace == nullptr) {
        html_ = introPage(lesson);
    } else {
        const QString lessonDir = QFileInfo(lesson.scenePath).absolutePath();
        // Many bodies: the page writes out one, the one last grabbed (else the first movable).
        DerivationOptions options;
        options.focusBody = derivationFocusBody(scene, focusBody_);
        html_ = buildLessonDerivation(*trace, scene, lessonDir, options).html;
    }
    view_->showStep(html_);
}

} // namespace rbw
