// CSV for spreadsheets and pandas: a header, then one row per step (plus a first
// row for the initial state, step 0 at t = 0): time, per body x, r [w x y z], v, omega,
// then the energies. Values are read from the world after each step.
#pragma once

#include "physics/engine/world.h"

#include <QString>
#include <QTextStream>

namespace rbw {

class CsvWriter {
public:
    explicit CsvWriter(QTextStream& out) : out_(out) {}
    void writeHeader(const SceneDef& scene);
    void writeRow(const World& world);
    // The same with the diagnostics already computed (World::checkOutputs(d) checked them).
    void writeRow(const World& world, const Diagnostics& d);

private:
    QTextStream& out_;
};

} // namespace rbw
