#include "app/output/csv_output.h"

#include <QLocale>
#include <QStringList>

namespace rbw {

namespace {

// Shortest text that reads back as the same double.
QString exact(double x)
{
    return QString::number(x, 'g', QLocale::FloatingPointShortest);
}

// RFC 4180: a cell with a comma, quote or line break is quoted, quotes doubled.
QString cell(const QString& text)
{
    if (!text.contains(',') && !text.contains('"') && !text.contains('\n') && !text.contains('\r')) return text;
    return '"' + QString(text).replace('"', QStringLiteral("\"\"")) + '"';
}

} // namespace

void CsvWriter::writeHeader(const SceneDef& scene)
{
    QStringList columns{"step", "time"};
    for (const BodyDef& b : scene.bodies) {
        const QString n = QString::fromStdString(b.name);
        for (const char* c : {"x", "y", "z"}) columns << cell(QStringLiteral("%1.x_%2").arg(n, c));
        for (const char* c : {"w", "x", "y", "z"}) columns << cell(QStringLiteral("%1.r_%2").arg(n, c));
        for (const char* c : {"x", "y", "z"}) columns << cell(QStringLiteral("%1.v_%2").arg(n, c));
        for (const char* c : {"x", "y", "z"}) columns << cell(QStringLiteral("%1.omega_%2").arg(n, c));
    }
    columns << "kinetic_energy_translational" << "kinetic_energy_rotational" << "potential_energy"
            << "total_energy";
    out_ << columns.join(',') << '\n';
}

void CsvWriter::writeRow(const World& world)
{
    writeRow(world, world.diagnostics());
}

void CsvWriter::writeRow(const World& world, const Diagnostics& d)
{
    QStringList cells{QString::number(world.stepIndex()), exact(world.time())};
    for (const BodyState& s : world.states()) {
        for (int i = 0; i < 3; ++i) cells << exact(s.x_W[i]);
        for (double c : toWxyz(s.q_WB)) cells << exact(c);
        for (int i = 0; i < 3; ++i) cells << exact(s.v_W[i]);
        for (int i = 0; i < 3; ++i) cells << exact(s.omega_W[i]);
    }
    cells << exact(d.kineticTranslational) << exact(d.kineticRotational) << exact(d.potential)
          << exact(d.total);
    out_ << cells.join(',') << '\n';
}

} // namespace rbw
