// Reading what a student types as an answer ("Check my numbers" in the app): a number,
// a vector, a quaternion or a 3x3 matrix, in the forms one writes by hand:
//   (-2.4, 4.918, -1.765)   -2.4 4.918 -1.765   -2.4, 4.918, -1.765   [w x y z]
//   64/27 or -5/27 in any component
//   4.8 0 0; 0 9.836 0; 0 0 4.412   (or the three rows on three lines)
// Brackets ( ) [ ] { } are ignored; commas, semicolons, blanks and line breaks all
// separate numbers. The result is flattened as the checker wants it (a matrix row by
// row, a quaternion [w, x, y, z]). Formatting only: nothing physical is computed.
#pragma once

#include <QString>

#include <vector>

namespace rbw {

struct ParsedAnswer {
    std::vector<double> values;   // flattened; empty when the text cannot be read
    QString error;                // "3 numbers expected, got 2", "cannot read '4.9.1'"
    bool ok() const { return error.isEmpty(); }
};

// Reads `text` as `expectedCount` numbers (1, 3, 4 or 9). Blank text is an error too
// ("nothing written"); the caller decides whether a blank cell is checked at all.
ParsedAnswer parseAnswerText(const QString& text, int expectedCount);

// The inverse, for answers loaded from a file: "-2.4", "(-2.4, 4.918, -1.765)",
// "[1 0 0 0]" for a quaternion, "4.8 0 0; 0 9.836 0; 0 0 4.412" for a matrix.
QString answerText(const std::vector<double>& values);

} // namespace rbw
