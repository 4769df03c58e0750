// A lesson's text (lessons/<lesson>/lesson.md) with its setup numbers filled in from
// the scene that runs (issue 20, item 2). After New numbers or an edit in the scene
// editor the text's setup follows the scene, and what the text works out for the
// published numbers is marked as such.
//
// In the text, a setup number is written as a placeholder with the published value
// after "=":
//
//   {{scene:mass@box = 2}}          {{scene:force#0 = (1, 1, 0)}}     {{scene:h = 2}}
//
// Keys: h, g, steps, restitution, friction (the scene's); mass, size, position,
// velocity, omega, orientation ([w, x, y, z]), degrees (the turn's angle) of a body
// (@name); force, point (forces[i], #i) and torque (torques[i], #i). ".x", ".y",
// ".z" pick a component of a vector.
//
// A placeholder whose scene value agrees with the published one (every number of the
// published text, to the digits written there) shows the published text as written;
// else the scene's value in bold with "(published: …)" beside it, and the text starts
// with a note that the worked values below are for the published numbers.
// Formatting only: every number is a scene input.
#pragma once

#include "physics/engine/scene.h"

#include <QString>
#include <QStringList>

namespace rbw {

struct FilledLessonText {
    QString markdown;       // the text to show
    bool ownNumbers = false;   // the scene is not the published one (a note says so)
    int placeholders = 0;   // how many were filled
    QStringList changed;    // "mass@box: 4.5 (published: 2)", one per differing placeholder
    QStringList errors;     // "line N: {{…}}: reason" (unknown key, body, index, bad published value)
};

// published: false when the caller knows the scene is not the lesson's own file
// (new numbers, an edit); the note is then shown even if no placeholder differs.
FilledLessonText fillLessonText(const QString& markdown, const SceneDef& scene, bool published = true);

} // namespace rbw
