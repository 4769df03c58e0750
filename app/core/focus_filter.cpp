#include "app/core/focus_filter.h"

#include <vector>

namespace rbw {

int derivationFocusBody(const SceneDef& scene, int wanted)
{
    const int n = static_cast<int>(scene.bodies.size());
    if (n <= kDerivationAllBodiesMax) {
        return -1;
    }
    if (wanted >= 0 && wanted < n) {
        return wanted;
    }
    int first = 0;
    while (first < n - 1 && scene.bodies[first].fixed) {
        ++first;
    }
    return first;
}

std::vector<int> focusContacts(const StepTrace& trace, int body)
{
    std::vector<int> out;
    for (size_t c = 0; c < trace.contacts.size(); ++c) {
        if (trace.contacts[c].bodyA == body || trace.contacts[c].bodyB == body) out.push_back(static_cast<int>(c));
    }
    return out;
}

StepTrace focusTrace(const StepTrace& trace, int body)
{
    StepTrace out;
    out.step = trace.step;
    out.time = trace.time;
    out.diagnostics = trace.diagnostics;
    // Every body's state when the step began, by body index (the entries keep theirs).
    out.start = trace.start;
    // Contact c of the trace becomes contact renumber[c] of the selection, or -1.
    std::vector<int> renumber(trace.contacts.size(), -1);
    for (int c : focusContacts(trace, body)) {
        renumber[static_cast<std::size_t>(c)] = static_cast<int>(out.contacts.size());
        out.contacts.push_back(trace.contacts[static_cast<std::size_t>(c)]);
    }
    for (const TraceEntry& e : trace.entries) {
        if (e.info->stage == Stage::Collision && e.index >= 0) {
            // A contact's row: kept with its contact, under the new number.
            if (e.index < static_cast<int>(renumber.size()) && renumber[e.index] >= 0) {
                TraceEntry kept = e;
                kept.index = renumber[e.index];
                out.entries.push_back(kept);
            }
        } else if (e.body == body || e.body < 0) {
            out.entries.push_back(e);
        }
    }
    return out;
}

} // namespace rbw
