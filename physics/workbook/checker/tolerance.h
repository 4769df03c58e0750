// When a student's number is "the same" as a reference (issue 10, issue 21 item 4).
//
// An answer v matches a reference e when |v_i - e_i| <= rel * max_j |e_j| + extra_i for
// every component (a quaternion also as -e: q and -q are one rotation). `extra` is the
// rounding carried in from the student's earlier answers (checker.h).
//
// Right to 3 significant figures: |v_i - e_i| <= half a unit of the third significant
// figure of max_j |e_j|, i.e. 0.5 * 10^(floor(log10 max_j |e_j|) - 2). I0 = 0.1016667
// written 0.102 is 0.00033 off, within 0.0005: right to 3 figures, not to the 4 of the
// check's tolerance (0.0001).
#pragma once

#include "physics/engine/body.h"

#include <vector>

namespace rbw::checking {

using Values = std::vector<double>;

Vec3 vecOf(const Values& v);   // 3 numbers
Mat3 matOf(const Values& v);   // 9 numbers, row by row
Values flatVec(const Vec3& v);
Values flatMat(const Mat3& m);
double maxAbs(const Values& v);

// |given_i - ref_i| <= tol + extra_i for every i (a quaternion also against -ref).
// Never when a reference component or its tolerance is not finite: a value recomputed
// through a denominator near zero (1.8e8 / 1e-300 = inf) matches no answer (issue 22).
bool matchesWithin(const Values& given, const Values& ref, double tol, const Values& extra = {});
// The check's tolerance: tol = rel * max|ref|.
bool matches(const Values& given, const Values& ref, double rel, const Values& extra = {});

// Half a unit of the third significant figure of max|ref| (0 for a zero reference).
double threeFigureHalfUnit(const Values& ref);
// Right when rounded to 3 significant figures (see above).
bool rightToThreeFigures(const Values& given, const Values& ref);

} // namespace rbw::checking
