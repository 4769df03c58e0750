// The quantities table's "Yours" column (Compare with my simulator → Open in the main
// window, issue 23): the student's own simulator's numbers for the state quantities its
// `state` line gives (x, v, ω and, when printed, r; docs/simulator-protocol.md), per
// body and step, beside the workbook's. A value differs when the diagnosis says so
// (physics/workbook/probes/probe_verdict.h, answerDifferences: the rule of the first
// divergence); the cell is then coloured as a wrong entry of Check my numbers, green as
// a right one otherwise, and its tooltip gives both numbers and the difference. It
// holds what it is given: it compares and computes nothing itself.
//
// A row gets a Yours cell when it shows the value a `state` line answers: in a step's
// trace the last entry of position, linear_velocity, angular_velocity or orientation
// of its body (the state after the step), before the first step the start's rows.
#pragma once

#include "physics/engine/trace.h"

#include <QColor>
#include <QString>

#include <string>
#include <vector>

namespace rbw {

struct StudentValue {
    long step = 0;             // the state after `step` steps (n)
    int body = 0;
    std::string quantityId;    // the trace id of its rows (q::position, linear_velocity, angular_velocity, orientation)
    std::vector<double> given;      // the student's numbers (3; orientation 4: w, x, y, z)
    std::vector<double> expected;   // the workbook's, as the diagnosis compares them
    double largest = 0.0;      // the largest |given - expected| of the components
    double tolerance = 0.0;    // the largest allowed
    bool differs = false;
};

class StudentColumn {
public:
    // The colours of Check my numbers (app/gui/panels/check/check_model.cpp): right, wrong.
    static QColor agreeColour() { return QColor(0xc6, 0xef, 0xce); }
    static QColor differColour() { return QColor(0xf8, 0xc4, 0xc4); }

    void set(std::vector<StudentValue> values, const QString& source)
    {
        values_ = std::move(values);
        source_ = source;
    }
    void clear() { values_.clear(); source_.clear(); }
    bool isEmpty() const { return values_.empty(); }
    // Who "yours" is: the program's command or the answers folder.
    const QString& source() const { return source_; }

    // The student's value for entry `entry` of `trace` (startOnly: the table shows the
    // state trace.step, before any step of it; else the state after step trace.step),
    // or nullptr when that row has none.
    const StudentValue* find(const StepTrace& trace, bool startOnly, int entry) const;
    // The student's numbers as the value type of the row (a vector, or a quaternion).
    static TraceValue valueOf(const StudentValue& v);
    // "Yours: (…)\nThe workbook's: (…)\n…": both numbers, the difference and the tolerance.
    static QString toolTip(const StudentValue& v, const QString& symbol);

private:
    std::vector<StudentValue> values_;
    QString source_;
};

} // namespace rbw
