#include "app/gui/panels/plots/quantity_series.h"

#include "app/core/step_history.h"


#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

namespace rbw {

namespace {

QByteArray csvField(const QString& text)
{
    QString t = text;
    if (t.contains(',') || t.contains('"')) t = '"' + t.replace('"', QStringLiteral("\"\"")) + '"';
    return t.toUtf8();
}

} // namespace

QByteArray csvNumber(double x)
{
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
    return QByteArray(buffer, static_cast<int>(r.ptr - buffer));
}

bool QuantityKey::matches(const TraceEntry& e) const
{
    return e.body == body && e.index == index && id == QLatin1String(e.info->id);
}

double normOf(const std::vector<double>& values)
{
    double sum = 0.0;
    for (double v : values) sum += v * v;
    return std::sqrt(sum);
}

QuantitySeries::QuantitySeries(QuantityKey key, QString label, QString unit, QString symbol)
    : key_(std::move(key))
    , label_(std::move(label))
    , unit_(std::move(unit))
    , symbol_(std::move(symbol))
{
}

QStringList QuantitySeries::componentNames() const
{
    switch (kind_) {
    case 0: return {QString()};
    case 1: return {"x", "y", "z"};
    case 2: return {"w", "x", "y", "z"};
    case 3: return {"11", "12", "13", "21", "22", "23", "31", "32", "33"};
    default: return {};
    }
}

QString QuantitySeries::componentSymbol(int component) const
{
    const QStringList names = componentNames();
    if (component < 0 || component >= names.size() || names[component].isEmpty()) return symbol();
    if (kind_ != 3) return QStringLiteral("%1_%2").arg(symbol(), names[component]);
    // Row and column as subscript digits: R₂₂.
    QString sub;
    for (QChar c : names[component]) sub += QChar(0x2080 + (c.unicode() - '0'));
    return symbol() + sub;
}

QString QuantitySeries::componentLabel(int component) const
{
    const QString& sym = symbol();
    const QString named = componentSymbol(component);
    // "ω (racket)" -> "ω_y (racket)"; a label not starting with the symbol keeps it
    // whole and names the component after it.
    if (label_.startsWith(sym)) return named + label_.mid(sym.size());
    return named == sym ? label_ : QStringLiteral("%1 %2").arg(label_, named);
}

bool QuantitySeries::append(const StepTrace& trace)
{
    if (!samples_.empty() && trace.step <= samples_.back().step) return false;
    if (!std::isfinite(trace.time)) return false;
    for (const TraceEntry& e : trace.entries) {
        if (!key_.matches(e)) continue;
        std::vector<double> values = traceValueComponents(e.value);
        for (double v : values) {
            if (!std::isfinite(v)) return false;   // never drawn
        }
        if (kind_ < 0) {
            kind_ = static_cast<int>(e.value.index());
            componentCount_ = static_cast<int>(values.size());
        } else if (kind_ != static_cast<int>(e.value.index())) {
            return false;
        }
        samples_.push_back(Sample{trace.step, trace.time, std::move(values)});
        return true;
    }
    return false;
}

void QuantitySeries::fillFromHistory(const StepHistory& history)
{
    samples_.clear();
    if (history.empty()) return;
    for (std::size_t i = 0; i <= history.cursor(); ++i) {
        const HistoryEntry& entry = history.at(i);
        if (entry.hasTrace) append(entry.trace.unpack());
    }
}

void QuantitySeries::truncateAfter(long lastStep)
{
    while (!samples_.empty() && samples_.back().step > lastStep) samples_.pop_back();
}

QList<QPointF> QuantitySeries::points(int component) const
{
    QList<QPointF> out;
    out.reserve(static_cast<qsizetype>(samples_.size()));
    for (const Sample& s : samples_) {
        if (component < 0) {
            out.append(QPointF(s.t, normOf(s.values)));
        } else if (component < static_cast<int>(s.values.size())) {
            out.append(QPointF(s.t, s.values[static_cast<std::size_t>(component)]));
        }
    }
    return out;
}

const QuantitySeries::Sample* QuantitySeries::sampleAt(long step) const
{
    // Samples are in step order; a contact field may skip steps.
    auto it = std::lower_bound(samples_.begin(), samples_.end(), step,
                               [](const Sample& s, long k) { return s.step < k; });
    return (it != samples_.end() && it->step == step) ? &*it : nullptr;
}

QByteArray QuantitySeries::csv(bool withNorm) const
{
    QByteArray out = "step,t";
    const QStringList names = componentNames();
    for (const QString& c : names) {
        out += ',' + csvField(c.isEmpty() ? label_ : QStringLiteral("%1_%2").arg(label_, c));
    }
    if (withNorm && componentCount_ > 1) out += ',' + csvField(QStringLiteral("|%1|").arg(label_));
    out += '\n';
    for (const Sample& s : samples_) {
        out += QByteArray::number(static_cast<qlonglong>(s.step)) + ',' + csvNumber(s.t);
        for (double v : s.values) out += ',' + csvNumber(v);
        if (withNorm && componentCount_ > 1) out += ',' + csvNumber(normOf(s.values));
        out += '\n';
    }
    return out;
}

} // namespace rbw
