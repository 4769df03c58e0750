// How a number the student can edit is shown, the same in the 3D view's overlay, the
// status line and the parameter fields: six significant digits, so h = 1/60 reads
// "0.0166667" everywhere (not "0.01666666667", of which an h box 7 characters wide
// showed only the tail "66666667"). A field shows the short text but keeps the
// exact value: the text it shows stands for that value, so Enter or leaving the field
// without typing never rounds h = 1/60 to 0.0166667 (fieldNumber).
#pragma once

#include <QString>

namespace rbw {

// Six significant digits, the shortest of 'f' and 'e' ("0.0166667", "0.001", "1e-05").
inline QString shortNumber(double x)
{
    return QString::number(x, 'g', 6);
}

// The number a field's text means, given the exact value the field shows: the shown
// text itself (shortNumber(shown), surrounding spaces ignored) is that exact value;
// anything else is read as typed. False in *ok when the text is no number.
inline double fieldNumber(const QString& text, double shown, bool* ok)
{
    const QString t = text.trimmed();
    if (t == shortNumber(shown)) {
        *ok = true;
        return shown;
    }
    return t.toDouble(ok);
}

} // namespace rbw
