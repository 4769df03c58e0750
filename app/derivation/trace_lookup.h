// Finding trace entries for a derivation: which entry a placeholder such as
// {{applied_force}} or {{angular_velocity@A}} means in the current context (body,
// force, probe, contact). Lookup only: it selects recorded numbers, it never
// computes one.
//
// Glossary
//   index kind   what an entry's `index` counts: a force, a couple, a probe, a contact
//                or a correction (None: the entry has index -1)
//   context      the body and the loop indices a template block is expanded in
#pragma once

#include "physics/engine/quantity_catalogue.h"
#include "physics/engine/trace.h"

#include <QString>

#include <string_view>
#include <vector>

namespace rbw {

// What the `index` of entries with this id counts: the catalogue's index kind
// (physics/engine/quantity_catalogue.h); None for an id that is not in the catalogue.
IndexKind indexKindOf(std::string_view id);

// The template names of the index kinds, "force", "torque", "probe", "contact",
// "stage", "correction" (physics' indexKindName) -> IndexKind; None if unknown.
IndexKind indexKindFromName(const QString& name);

struct LookupContext {
    int body = -1;   // -1: not fixed by the context
    int force = -1;
    int torque = -1;
    int probe = -1;
    int contact = -1;
    int correction = -1;
    int stage = -1;   // RK stage i

    int indexFor(IndexKind kind) const;
    void setIndex(IndexKind kind, int index);
};

struct LookupResult {
    const TraceEntry* entry = nullptr;
    QString problem;   // why entry is null: "not computed in this step", "ambiguous: ..."
    bool missing = false;   // true: simply not in this step's trace
};

// The entry with this id in the context. explicitIndex / explicitBody (-1: none)
// override the context. Rules (docs/derivation-templates.md):
//  - index: the explicit one, else the context's index of the id's kind, else -1 for
//    kind None; if the context has no index of that kind and exactly one entry
//    exists, that one.
//  - body: the explicit one; contact and correction quantities ignore the body (their
//    index names them); else the context's body; else the only body that has the entry.
LookupResult lookupEntry(const StepTrace& trace, std::string_view id, const LookupContext& context,
                         int explicitIndex = -1, int explicitBody = -1);

// The value a body had when contact `contact` started: the latest entry before that
// contact's first entry among <id> (integration), <id>_a and <id>_b (earlier contacts)
// recorded for this body. For ids linear_velocity, angular_velocity, angular_momentum.
const TraceEntry* valueBeforeContact(const StepTrace& trace, std::string_view id, int body, int contact);

// The distinct indices of entries with this id (ascending), optionally only for one body.
std::vector<int> indicesOf(const StepTrace& trace, std::string_view id, int body = -1);

// Bodies (ascending) that have at least one entry in the trace.
std::vector<int> bodiesInTrace(const StepTrace& trace);

// The integrator that computed body b's integration in this step, by the source file
// of its integration entries (the longest such name: one integrator may use another's code) (physics/engine/integrators/<name>.cpp, the registry's
// name with '-' for '_'); empty if the trace does not tell (no integration entries, or
// only shared code). The scene may have switched integrators since the step was taken
// (issue 20): the derivation names the one that ran.
QString tracedIntegrator(const StepTrace& trace, int body);

} // namespace rbw

namespace rbw {
// False if any component is NaN or infinite (a view never shows those as results).
bool isFiniteValue(const TraceValue& value);
}
