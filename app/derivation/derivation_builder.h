// The step-by-step derivation of one step as an HTML document: a lesson's template
// (derivation.md, see docs/derivation-templates.md and derivation_template.h) filled
// in from the step's trace, or the generic fallback when a lesson has none.
//
// Every number comes from the trace (through value_format's latexValue); the scene
// definition gives only names and the inputs h, M, size and g. A placeholder whose
// entry is not in this step's trace shows a red "not computed in this step" note, never
// a number; template syntax errors are listed as "file:line: message" at the top of
// the page, above the fallback.
#pragma once

#include "app/derivation/derivation_page.h"
#include "physics/engine/scene.h"
#include "physics/engine/trace.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace rbw {

struct DerivationOptions {
    QString katexUrl = defaultKatexUrl();   // where katex.min.js/.css are, with a trailing slash
    int digits = 7;                         // significant digits of every number
    // A scene with many bodies (app/core/focus_filter.h): >= 0 writes out only this
    // body, the world-level rows and the contacts it takes part in (focusTrace), under
    // a note at the top of the page that says so. -1: every body.
    int focusBody = -1;
};

// One filled-in derivation row, as LaTeX: where it comes from ("file:line" of the
// template or of the integrator's section), the formula, the formula with the numbers
// put in (empty for a two-cell row) and the result.
struct DerivationRow {
    QString where;
    QString formula;
    QString substituted;
    QString result;
};

struct DerivationDocument {
    QString html;          // a complete document, starting with <!DOCTYPE html>
    QStringList errors;    // template errors, "file:line: message"
    QStringList notes;     // placeholders without a value here, "file:line: {{id}}: reason"
    bool fallback = false; // the generic derivation was used (no template, or a broken one)
    std::vector<DerivationRow> rows;   // every row of a template page, in page order
};

// Fills a template (its text, and the label used in messages) from the trace.
DerivationDocument buildDerivation(const StepTrace& trace, const SceneDef& scene, const QString& templateText,
                                   const QString& templateLabel, const DerivationOptions& options = {});

// Every traced quantity, grouped by stage and body/contact, as formula = value.
DerivationDocument buildFallbackDerivation(const StepTrace& trace, const SceneDef& scene,
                                           const DerivationOptions& options = {});

// lessonDirectory/derivation.md if it exists, else the fallback.
DerivationDocument buildLessonDerivation(const StepTrace& trace, const SceneDef& scene,
                                         const QString& lessonDirectory, const DerivationOptions& options = {});

} // namespace rbw
