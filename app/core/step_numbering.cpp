#include "app/core/step_numbering.h"

#include <QCoreApplication>

namespace rbw::steps {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("rbw::steps", text); }

} // namespace

QString timeName(long n)
{
    QString digits = QString::number(n);
    for (QChar& c : digits) {
        if (c.isDigit()) c = QChar(0x2080 + c.digitValue());   // ₀ … ₉
    }
    return QStringLiteral("t") + digits;
}

QString stepSpan(long k)
{
    return tr("step k = %1 (%2 → %3)").arg(k).arg(timeName(k), timeName(k + 1));
}

QString stateName(long n)
{
    return n > 0 ? tr("after step k = %1").arg(n - 1) : beforeStep(0);
}

QString beforeStep(long k)
{
    return tr("before step k = %1").arg(k);
}

QString stepsTaken(long n)
{
    return n == 1 ? tr("1 step taken") : tr("%1 steps taken").arg(n);
}

} // namespace rbw::steps
