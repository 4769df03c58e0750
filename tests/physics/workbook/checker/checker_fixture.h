// What the checker's tests share: a lesson's world at the start of step k with the trace
// of that step, an answer, and whether a result names a mistake (tst_checker,
// tst_diagnosis, tst_follow_through).
#pragma once

#include "tests/test_support.h"

#include "physics/workbook/checker/checker.h"
#include "physics/engine/quantities.h"
#include "physics/engine/world.h"

#include <algorithm>
#include <cstring>
#include <memory>

namespace rbw::test {

// The world at the start of step k of a lesson and the trace of that step.
struct StepUnderTest {
    std::unique_ptr<rbw::World> before;
    rbw::StepTrace trace;
};

inline StepUnderTest stepOf(const char* lesson, int k)
{
    StepUnderTest s;
    s.before = std::make_unique<rbw::World>(lessonScene(QString::fromLatin1(lesson)));
    for (int i = 0; i < k; ++i) {
        if (!s.before->step().ok) qFatal("blew up");
    }
    const rbw::WorldSnapshot snap = s.before->snapshot();
    if (!s.before->step(&s.trace).ok) qFatal("blew up");
    s.before->restore(snap);
    return s;
}

inline rbw::Answer answer(const char* id, int body, std::vector<double> v, int contact = -1, int index = -1)
{
    rbw::Answer a;
    a.quantity = id;
    a.body = body;
    a.contact = contact;
    a.index = index;
    a.value = std::move(v);
    return a;
}

// Named with confidence.
inline bool has(const rbw::AnswerResult& r, const char* mistake)
{
    return std::any_of(r.mistakes.begin(), r.mistakes.end(), [&](const char* m) { return std::strcmp(m, mistake) == 0; });
}

// Named as possible only.
inline bool mayBe(const rbw::AnswerResult& r, const char* mistake)
{
    return std::any_of(r.possibleMistakes.begin(), r.possibleMistakes.end(),
                       [&](const rbw::PossibleMistake& p) { return std::strcmp(p.id, mistake) == 0; });
}

inline std::vector<double> flatValue(const rbw::TraceValue& v)
{
    const QList<double> l = flatten(v);
    return std::vector<double>(l.begin(), l.end());
}

// The workbook's value of a body quantity in the trace.
inline std::vector<double> traced(const rbw::StepTrace& t, const char* id, int body, int index = -1)
{
    const rbw::TraceEntry* e = t.find(id, body, index);
    if (e == nullptr) qFatal("no %s in the trace", id);
    return flatValue(e->value);
}

inline int count(const std::vector<rbw::AnswerResult>& r, rbw::Verdict v)
{
    return static_cast<int>(std::count_if(r.begin(), r.end(), [&](const rbw::AnswerResult& x) { return x.verdict == v; }));
}

} // namespace rbw::test
