#include "app/gui/panels/editor/scene_editor_fields.h"

#include "app/gui/panels/editor/scene_editor_model.h"

#include <QLocale>
#include <QRegularExpression>

#include <cmath>

namespace rbw::editorfields {

namespace {

using K = sceneformat::Key;
using sceneformat::Section;
using sceneformat::Type;

Section sectionOf(int group)
{
    switch (group) {
    case SceneEditorModel::Bodies: return Section::Body;
    case SceneEditorModel::Forces: return Section::Force;
    case SceneEditorModel::Torques: return Section::Torque;
    case SceneEditorModel::Probes: return Section::Probe;
    case SceneEditorModel::Planes: return Section::Plane;
    case SceneEditorModel::Pairs: return Section::Pair;
    default: return Section::Scene;
    }
}

} // namespace

namespace {

QList<Field> makeFields(int group)
{
    QList<Field> fields;
    const Section section = sectionOf(group);
    for (const sceneformat::KeyRow& r : sceneformat::rows()) {
        if (r.section != section) continue;
        if (r.id == K::EnergyJump) {
            fields << Field{K::EnergyJumpFactor} << Field{K::EnergyJumpFloor};
        } else if (r.type == Type::NamePair) {
            fields << Field{r.id, 0} << Field{r.id, 1};
        } else if (r.type != Type::List && r.id != K::Push) {   // the push has no group of its own
            fields << Field{r.id};
        }
    }
    return fields;
}

} // namespace

QList<Field> fieldsOf(int group)
{
    // Built once: data() asks for every cell.
    static const QList<QList<Field>> all = [] {
        QList<QList<Field>> lists;
        for (int g = 0; g < SceneEditorModel::GroupCount; ++g) lists << makeFields(g);
        return lists;
    }();
    return all.value(group);
}

QString fieldName(const Field& f)
{
    if (f.index >= 0) return QStringLiteral("%1[%2]").arg(sceneformat::key(f.key)).arg(f.index);
    if (sceneformat::row(f.key).section == Section::EnergyJump) {
        return sceneformat::key(K::EnergyJump) + '.' + sceneformat::key(f.key);
    }
    return sceneformat::key(f.key);
}

QString fieldUnit(const Field& f) { return QString::fromUtf8(sceneformat::row(f.key).unit); }

QString fieldMeaning(const Field& f)
{
    if (f.index == 0) return QStringLiteral("a body");
    if (f.index == 1) return QStringLiteral("a body or a plane");
    return QString::fromUtf8(sceneformat::row(f.key).meaning);
}

bool isCheckBox(const Field& f)
{
    const sceneformat::KeyRow& r = sceneformat::row(f.key);
    return r.type == Type::Boolean && *r.fallback;
}

QString num(double x) { return QString::number(x, 'g', QLocale::FloatingPointShortest); }

QString vecText(const Vec3& v) { return QStringLiteral("%1, %2, %3").arg(num(v.x()), num(v.y()), num(v.z())); }

QString quoted(const QString& text) { return QStringLiteral("\"%1\"").arg(text.left(40)); }

// Numbers from "1, 2, 3", "[1 2 3]" or "1;2;3" (C locale: a point is the decimal sign).
bool parseNumbers(const QString& text, int count, QList<double>* out, QString* error)
{
    QString t = text.trimmed();
    if (t.startsWith('[') && t.endsWith(']')) t = t.mid(1, t.size() - 2);
    static const QRegularExpression separator(QStringLiteral("[,;\\s]+"));
    const QStringList parts = t.split(separator, Qt::SkipEmptyParts);
    if (parts.size() != count) {
        *error = QStringLiteral("must be %1 numbers separated by commas, got %2").arg(count).arg(quoted(text));
        return false;
    }
    for (const QString& p : parts) {
        bool ok = false;
        const double x = QLocale::c().toDouble(p, &ok);
        if (!ok || !std::isfinite(x)) {
            *error = QStringLiteral("must be %1 finite numbers, got %2").arg(count).arg(quoted(p));
            return false;
        }
        out->append(x);
    }
    return true;
}

bool parseNumber(const QString& text, double* x, QString* error)
{
    bool ok = false;
    *x = QLocale::c().toDouble(text.trimmed(), &ok);
    if (!ok || !std::isfinite(*x)) {
        *error = QStringLiteral("must be a finite number, got %1").arg(quoted(text));
        return false;
    }
    return true;
}

// As the loader reads a whole number: no fraction, at most 9e15 in size.
bool parseWhole(const QString& text, long* n, QString* error)
{
    double x = 0;
    if (!parseNumber(text, &x, error)) return false;
    if (x != std::floor(x) || std::abs(x) > 9.0e15) {
        *error = QStringLiteral("must be a whole number from -9e15 to 9e15, got %1").arg(num(x));
        return false;
    }
    *n = static_cast<long>(x);
    return true;
}

bool parseVec(const QString& text, Vec3* v, QString* error)
{
    QList<double> n;
    if (!parseNumbers(text, 3, &n, error)) return false;
    *v = Vec3(n[0], n[1], n[2]);
    return true;
}

} // namespace rbw::editorfields
