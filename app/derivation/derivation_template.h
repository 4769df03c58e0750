// The derivation template language (docs/derivation-templates.md): a lesson's
// derivation.md parsed into blocks. Line based:
//
//   # / ## / ###  heading         "- " list item        blank line: paragraph break
//   = formula && substituted && result     one derivation row (1 to 3 cells)
//   $$ latex $$                   display math on one line
//   @foreach body|force|torque|probe|contact|correction ... [@else ...] @end
//   @body NAME ... @end           @if COND ... [@else ...] @end   (@ifnot COND)
//   @integration                  the current body's integrator's own section
//                                 (integrator_sections.h), expanded in place
//   @iterations                   in a contact loop: the manifold solver's impulses
//                                 after each iteration (ContactHeader::iterations)
//   <!-- comment -->              on one line, ignored
//
// Placeholders {{...}} inside any text are checked here (syntax, known ids) and
// filled in by the builder from the trace.
#pragma once

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rbw {

// One parsed {{...}}: [prefix:]name[[index]][@body][.selector]
struct Placeholder {
    QString prefix;     // "", "symbol", "formula", "unit", "scene", "pre", "start"
    QString name;       // trace id, scene key or meta name
    int index = -1;     // [i]
    QString body;       // @name (also @A / @B in a contact loop)
    QString selector;   // "x", "y", "z" (vector component) or "T" (transpose)
};

struct TemplateNode {
    enum class Kind { Heading, Paragraph, List, DisplayMath, Row, Loop, Body, If, Integration, Iterations };
    Kind kind = Kind::Paragraph;
    int line = 0;          // 1-based line in the template file
    int level = 0;         // heading level 1-3
    QString text;          // heading / paragraph / math text; loop kind; body name; condition
    QStringList items;     // row cells, or list items
    bool negate = false;   // @ifnot
    bool closed = false;   // parser state: a paragraph or list that takes no more lines
    std::vector<TemplateNode> children;
    std::vector<TemplateNode> elseChildren;
};

struct DerivationTemplate {
    QString label;   // the file name used in messages, e.g. "lessons/01-one-step/derivation.md"
    std::vector<TemplateNode> nodes;
};

struct TemplateParseResult {
    std::optional<DerivationTemplate> parsed;
    QStringList errors;   // "label:line: message", one per problem
    bool ok() const { return parsed.has_value(); }
};

TemplateParseResult parseDerivationTemplate(const QString& text, const QString& label);

// Parses the inside of one {{...}}; an empty string on success, else the reason.
QString parsePlaceholder(const QString& inside, Placeholder* out);

// Meta placeholders (text about the step, not trace values): body, i, A, B, feature,
// resolution, step, t, integrator (its title, e.g. "classical Runge-Kutta (RK4)": the
// current body's, else the scene's) and integrator_id (its name, e.g. "rk4").
// Conditions of @if / @ifnot: a quantity (present in the trace here), particle[@body]
// (angular response off), plane (contact B is a plane), convention=standard|course-template,
// model=course|manifold (the scene's contact model).
bool isMetaName(const QString& name);

} // namespace rbw
