// Follow-through (issue 10, issue 21 item 3): the value of a traced quantity as the
// student's own earlier answers make it. Every quantity the checker can recompute from
// earlier ones has a rule (follow_through.cpp, one equation each):
//   L' = L_n + h q,  v' = v_n + h F/M                     (explicit Euler bodies)
//   I0^-1 = (I0)^-1,  R = R(r),  I^-1 = R I0^-1 R^T,  omega = I^-1 L,
//   v_p = v + omega x (p - x)
//   v_rel = v_A(p) - v_B(p),  v_rel.n,  -(1 + c) v_rel.n,  the denominator,  J,
//   dv_A = (J n + J_t t)/M_A,  dL_A = x_a x (J n + J_t t),  v'_A = v_A + dv_A,
//   L'_A = L_A + dL_A,  omega'_A = I_A^-1 L'_A  (and B's with the opposite impulse).
// An input the student wrote is theirs (with its rounding); one they did not write is
// recomputed from theirs where a rule can, else the workbook's.
#pragma once

#include "physics/workbook/checker/tolerance.h"
#include "physics/engine/trace.h"

#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace rbw {
class World;
}

namespace rbw::checking {

// Which answer: a body quantity (body, index) or a contact quantity (contact).
struct AnswerKey {
    std::string id;
    int body = -1, contact = -1, index = -1;
    bool operator<(const AnswerKey& o) const
    {
        return std::tie(id, body, contact, index) < std::tie(o.id, o.body, o.contact, o.index);
    }
    bool operator==(const AnswerKey& o) const { return !(*this < o) && !(o < *this); }
    std::string name() const;   // "torque", "point_velocity #1"
};

// The trace entry of an answer (nullptr when the workbook has none).
const TraceEntry* traceEntryOf(const StepTrace& trace, const AnswerKey& k);

// A student's answer as the later ones read it.
struct GivenAnswer {
    Values value;
    Values rounding;                  // per component: what writing it down may have lost
    bool right = false;               // correct or imprecise
    std::vector<AnswerKey> wrongFrom; // the wrong answers it is (or follows from)
};

struct Recomputed {
    bool ok = false;
    bool student = false;             // some student answer went into it
    Values v;
    Values err;                       // rounding carried in, per component
    std::vector<AnswerKey> wrongFrom; // the student's wrong answers that went into it
};

class FollowThrough {
public:
    FollowThrough(const World& before, const StepTrace& trace) : w_(before), t_(trace) {}

    void give(const AnswerKey& k, GivenAnswer g) { given_[k] = std::move(g); }
    // `k` from the answers given so far (ok and student only when a rule reads one).
    Recomputed recompute(const AnswerKey& k) const { return recompute(k, 0); }

private:
    Recomputed recompute(const AnswerKey& k, int depth) const;
    Recomputed valueOf(const AnswerKey& k, int depth) const;

    const World& w_;
    const StepTrace& t_;
    std::map<AnswerKey, GivenAnswer> given_;
};

} // namespace rbw::checking
