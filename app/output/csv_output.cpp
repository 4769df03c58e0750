#include "app/output/csv_output.h"

#include "physics/engine/diagnostic_catalogue.h"
#include "physics/engine/quantities.h"

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

// The world's energies after the bodies' columns, in this order.
constexpr const DiagnosticInfo<Diagnostics>* kEnergyColumns[] = {&diag::kinetic_translational, &diag::kinetic_rotational,
                                                                 &diag::potential, &diag::total};

} // namespace

// The columns, named after the catalogues (quantity_catalogue.h, diagnostic_catalogue.h):
// NAME.position_x, NAME.orientation_w, NAME.linear_velocity_x, NAME.angular_velocity_x
// per body, then the world's energies. writeRow() writes the same values in this order.
void CsvWriter::writeHeader(const SceneDef& scene)
{
    QStringList columns{"step", "time"};
    const auto components = [&](const QString& body, const QuantityInfo& q, std::initializer_list<const char*> axes) {
        for (const char* c : axes) columns << cell(QStringLiteral("%1.%2_%3").arg(body, QLatin1String(q.id), QLatin1String(c)));
    };
    for (const BodyDef& b : scene.bodies) {
        const QString n = QString::fromStdString(b.name);
        components(n, q::position, {"x", "y", "z"});
        components(n, q::orientation, {"w", "x", "y", "z"});   // [w, x, y, z], math_types.h
        components(n, q::linear_velocity, {"x", "y", "z"});
        components(n, q::angular_velocity, {"x", "y", "z"});
    }
    for (const DiagnosticInfo<Diagnostics>* d : kEnergyColumns) {
        columns << QString::fromLatin1(d->id.data(), static_cast<qsizetype>(d->id.size()));
    }
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
    for (const DiagnosticInfo<Diagnostics>* info : kEnergyColumns) {
        cells << exact(d.*(info->scalar));
    }
    out_ << cells.join(',') << '\n';
}

} // namespace rbw
