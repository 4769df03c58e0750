// The derivation of one integrator's step for one body, which a lesson template pulls
// in with `@integration` (docs/derivation-templates.md). Each integrator has its own
// section, app/derivation/integrators/<name>.md, written in the template language
// with every start-of-step value substituted ({{start:...}}), followed by the rows
// every integrator of its kind shares: derived.md (R = R(r), I^-1, omega, after a
// quaternion update) or derived-from-matrix.md (I^-1 and omega from the integrator's R).
// The files are compiled into the library as Qt resources and parsed once.
#pragma once

#include "app/derivation/derivation_template.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace rbw {

struct IntegratorSection {
    QString label;                  // "app/derivation/integrators/rk4.md", for messages
    std::vector<TemplateNode> nodes;
    QStringList errors;             // parse errors, "label:line: message"; no nodes then
};

// The sections to expand for a body that uses this integrator, in order; for an
// unknown name, one section holding the error.
std::vector<const IntegratorSection*> integratorSections(const QString& integratorName);

} // namespace rbw
