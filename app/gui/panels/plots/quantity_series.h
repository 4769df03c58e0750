// Any traced quantity over time, for "Plot over time": the values one trace entry
// (a quantity id, a body and an index: which force, probe or contact) took in each
// recorded step, read from the step traces the session recorded. Nothing is
// recomputed: a sample is the entry's value as the physics recorded it; the only
// arithmetic is the Euclidean length |v| when the student asks for the norm.
//
// A contact field exists only in the steps that have that contact: the series then
// has samples in those steps only (no value is invented for the others).
//
// No widgets here: filled, truncated and written to CSV without a window.
#pragma once

#include "physics/engine/trace.h"

#include <QByteArray>
#include <QList>
#include <QPointF>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace rbw {

class StepHistory;

// Which trace entry: the quantity's id (physics/engine/quantity_catalogue.h), the body (-1
// for a world-level entry) and the index (-1 when there is one per body).
struct QuantityKey {
    QString id;
    int body = -1;
    int index = -1;

    bool matches(const TraceEntry& e) const;
    bool operator==(const QuantityKey&) const = default;
};

class QuantitySeries {
public:
    struct Sample {
        long step = 0;          // the step k whose trace holds the value
        double t = 0.0;         // StepTrace::time, the end of step k
        std::vector<double> values;   // 1 (scalar), 3 (vector), 4 (w x y z), 9 (row by row)
    };

    QuantitySeries() = default;
    // label: "ω (racket)" (for titles, the legend and the CSV), unit: "rad/s",
    // symbol: "ω" (the axis title; the label when empty).
    QuantitySeries(QuantityKey key, QString label, QString unit, QString symbol = {});

    const QuantityKey& key() const { return key_; }
    const QString& label() const { return label_; }
    const QString& unit() const { return unit_; }
    const QString& symbol() const { return symbol_.isEmpty() ? label_ : symbol_; }

    // The component names of the value kind: {""} scalar, {x,y,z}, {w,x,y,z},
    // {11,12,...,33}; empty until the first sample.
    QStringList componentNames() const;
    int componentCount() const { return componentCount_; }
    // A component's name after the quantity catalogue's symbol: ω_y for a vector or
    // a quaternion, R₂₂ for a matrix (row, column), the symbol for a scalar; and the
    // label with that symbol in place of the quantity's ("ω_y (racket)").
    QString componentSymbol(int component) const;
    QString componentLabel(int component) const;

    // Reads the entry from a step's trace; false (nothing stored) if the trace does
    // not hold it, a value is not finite, or the step is not after the last sample.
    bool append(const StepTrace& trace);
    // Every recorded step of the history up to and including its current entry.
    void fillFromHistory(const StepHistory& history);
    // Keeps the samples of steps k <= lastStep (after a step back or a scrub to the
    // state after step lastStep, whose world stepIndex() is lastStep + 1).
    void truncateAfter(long lastStep);
    void clear() { samples_.clear(); }

    const std::vector<Sample>& samples() const { return samples_; }
    int sampleCount() const { return static_cast<int>(samples_.size()); }
    // (t, component c), or (t, |v|) for component -1.
    QList<QPointF> points(int component) const;
    // The sample of step k, or nullptr.
    const Sample* sampleAt(long step) const;

    // "step,t,<label>_x,..." then one row per sample, numbers as the CLI writes them
    // (the shortest text that reads back as the same double).
    QByteArray csv(bool withNorm) const;

private:
    QuantityKey key_;
    QString label_;
    QString unit_;
    QString symbol_;
    int componentCount_ = 0;
    int kind_ = -1;   // TraceValue's alternative
    std::vector<Sample> samples_;
};

// The shortest text that reads back as the same double (as the CLI's CSV).
QByteArray csvNumber(double x);

// A value's Euclidean length (for a scalar its absolute value).
double normOf(const std::vector<double>& values);

} // namespace rbw
