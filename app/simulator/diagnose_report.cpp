#include "app/simulator/diagnose_report.h"

#include "app/core/step_numbering.h"
#include "physics/workbook/checker/mistakes.h"
#include "physics/workbook/probes/probe_models.h"

#include <QJsonArray>
#include <QStringList>

#include <algorithm>

namespace rbw {

namespace {

QString numbers(const std::vector<double>& v)
{
    QStringList parts;
    for (double x : v) parts << QString::number(x, 'g', 9);
    return QLatin1Char('(') + parts.join(", ") + QLatin1Char(')');
}

QJsonArray jsonNumbers(const std::vector<double>& v)
{
    QJsonArray a;
    for (double x : v) a.append(x);
    return a;
}

QJsonArray jsonStrings(const std::vector<std::string>& v)
{
    QJsonArray a;
    for (const std::string& s : v) a.append(QString::fromStdString(s));
    return a;
}

// The ids of `scope`'s models (what a group cannot check).
std::vector<std::string> idsOfScope(probes::ProbeScope scope)
{
    std::vector<std::string> ids;
    for (const MistakeInfo& m : mistakeCatalogue()) {
        if (probes::scopeOf(m.mistake) == scope) ids.push_back(m.id);
    }
    return ids;
}

bool hasCollisionProbes(const DiagnoseRun& run)
{
    return std::any_of(run.probes.begin(), run.probes.end(), [](const probes::Probe& p) { return p.collides; });
}

QString templateName(const probes::TemplateTest& t)
{
    QString name = QString::fromStdString(t.name);
    if (!t.version.empty()) name += " (" + QString::fromStdString(t.version) + ")";
    return name;
}

QString vec(const Vec3& v)
{
    return numbers({v.x(), v.y(), v.z()});
}

const char* const kTemplateNote =
    "Both versions of TestRigidBodiesAfterForceApplication expect the template's world inverse inertia "
    "R^T I0^-1 R (transposed-inertia), the 2018 one also the template's quaternion product of that time; "
    "a correct simulator (R I0^-1 R^T) fails both, the December 2022 one (the template's current test) "
    "included. Lesson 8 (lessons/08-conventions) shows the two conventions side by side.";

QJsonValue templateJson(const DiagnoseRun& run)
{
    if (run.templateTests.empty()) return QJsonValue::Null;
    QJsonArray tests;
    for (const TemplateTestResult& r : run.templateTests) {
        QJsonObject t{{"name", QString::fromStdString(r.test->name)},
                      {"version", QString::fromStdString(r.test->version)},
                      {"expects", QString::fromStdString(r.test->expects)},
                      {"passed", !r.failure.has_value()}};
        if (r.failure) {
            const probes::TemplateAssert& a = r.test->asserts[r.failure->assertIndex];
            t["failure"] = QJsonObject{{"quantity", QString::fromStdString(a.quantity)},
                                       {"component", r.failure->component},
                                       {"expected", jsonNumbers({a.expected.x(), a.expected.y(), a.expected.z()})},
                                       {"given", jsonNumbers({r.failure->given.x(), r.failure->given.y(),
                                                              r.failure->given.z()})}};
        }
        tests.append(t);
    }
    return QJsonObject{{"tolerance", probes::kTemplateTolerance}, {"tests", tests}, {"note", kTemplateNote}};
}

void writeTemplateText(QTextStream& out, const DiagnoseRun& run)
{
    if (run.templateTests.empty()) return;
    out << "the template's public tests (PublicRigidBodiesTests, |yours - expected| <= "
        << probes::kTemplateTolerance << "):\n";
    for (const TemplateTestResult& r : run.templateTests) {
        out << "  " << templateName(*r.test) << "  ";
        if (r.failure) {
            const probes::TemplateAssert& a = r.test->asserts[r.failure->assertIndex];
            out << "fails: " << QString::fromStdString(a.quantity) << " expected " << vec(a.expected) << ", yours "
                << vec(r.failure->given);
        } else {
            out << "passes";
        }
        out << "\n    it expects " << QString::fromStdString(r.test->expects) << '\n';
    }
    out << kTemplateNote << '\n';
}

// RFC 4180: quoted when it holds a comma, a quote or a line end.
QString csvField(const QString& s)
{
    if (!s.contains(',') && !s.contains('"') && !s.contains('\n') && !s.contains('\r')) return s;
    return '"' + QString(s).replace("\"", "\"\"") + '"';
}

QString joined(const std::vector<double>& v)
{
    QStringList parts;
    for (double x : v) parts << QString::number(x, 'g', 9);
    return parts.join(' ');
}

QString joined(const std::vector<std::string>& v)
{
    QStringList parts;
    for (const std::string& x : v) parts << QString::fromStdString(x);
    return parts.join(';');
}

} // namespace

QJsonObject diagnoseJson(const DiagnoseRun& run)
{
    const probes::SimulatorDiagnosis& d = run.diagnosis;
    QJsonObject doc;
    doc["simulator"] = run.sourceKind == QLatin1String("simulator") ? QJsonValue(run.source) : QJsonValue::Null;
    if (run.sourceKind != QLatin1String("simulator")) doc["answers_from"] = run.source;
    doc["probes_group"] = run.group;
    doc["tolerance"] = QJsonObject{{"relative", probes::kRelativeTolerance},
                                   {"of", "the largest |value| of that quantity (x, v, omega or r) in the probe"}};
    doc["verdict"] = QString::fromLatin1(probes::verdictName(d.verdict));
    doc["mistakes"] = jsonStrings(d.mistakes);
    doc["possible_mistakes"] = jsonStrings(d.possibleMistakes);
    doc["possible_explanations"] = jsonStrings(d.possibleExplanations);   // "a", or a pair "a + b"
    QJsonArray details;
    for (const std::vector<std::string>* ids : {&d.mistakes, &d.possibleMistakes}) {
        for (const std::string& id : *ids) {
            if (const MistakeInfo* m = findMistake(id)) {
                details.append(QJsonObject{{"id", m->id}, {"equation", m->equation}, {"explanation", m->explanation}});
            }
        }
    }
    doc["mistake_details"] = details;
    if (hasCollisionProbes(run)) {
        QJsonArray fits;
        for (const probes::RestitutionOf& r : d.restitution) {
            fits.append(QJsonObject{{"model", QString::fromStdString(r.model)}, {"c", r.c}});
        }
        doc["restitution"] = fits;
    } else {
        doc["restitution"] = QJsonValue::Null;
    }
    if (d.firstDivergence) {
        const probes::Divergence& f = *d.firstDivergence;
        doc["first_divergence"] = QJsonObject{
            {"probe", d.divergenceProbe + 1},
            {"probe_name", QString::fromStdString(run.probes[d.divergenceProbe].name)},
            {"step", f.step},
            {"body", f.body},
            {"quantity", QString::fromStdString(f.quantity)},
            {"component", f.component},
            {"expected", jsonNumbers(f.expected)},
            {"given", jsonNumbers(f.given)},
        };
    } else {
        doc["first_divergence"] = QJsonValue::Null;
    }
    QJsonArray rows;
    for (std::size_t p = 0; p < d.probes.size(); ++p) {
        rows.append(QJsonObject{{"probe", static_cast<int>(p) + 1},
                                {"name", QString::fromStdString(run.probes[p].name)},
                                {"purpose", QString::fromStdString(run.probes[p].purpose)},
                                {"matches", d.probes[p].matchesRight},
                                {"reproduced_by", jsonStrings(d.probes[p].reproducedBy)}});
    }
    doc["probes"] = rows;
    QJsonObject notChecked{{"hand_only", jsonStrings(idsOfScope(probes::ProbeScope::HandOnly))}};
    if (!hasCollisionProbes(run)) notChecked["collision"] = jsonStrings(idsOfScope(probes::ProbeScope::Collision));
    doc["not_checked"] = notChecked;
    doc["template_tests"] = templateJson(run);
    return doc;
}

void writeDiagnoseText(QTextStream& out, const DiagnoseRun& run)
{
    const probes::SimulatorDiagnosis& d = run.diagnosis;
    out << "rbw diagnose: " << run.probes.size() << ' '
        << (run.group == QLatin1String("all") ? QStringLiteral("probes (motion and collision)") : run.group + " probes");
    if (run.sourceKind == QLatin1String("simulator")) out << " through \"" << run.source << "\"\n";
    else out << ", the answers in " << run.source << '\n';
    out << "verdict: " << probes::verdictName(d.verdict) << '\n';
    auto describe = [&out](const std::string& id) {
        const MistakeInfo* m = findMistake(id);
        if (m == nullptr) return;
        out << "  " << m->id << ": " << m->equation << '\n' << "    " << m->explanation << '\n';
    };
    if (d.mistakes.size() == 1) out << "mistake:\n";
    if (d.mistakes.size() > 1) out << "mistakes (the two together explain your answers):\n";
    for (const std::string& id : d.mistakes) describe(id);
    if (!d.possibleMistakes.empty()) {
        QStringList each;
        for (const std::string& e : d.possibleExplanations) each << QString::fromStdString(e);
        out << "possible mistakes (each of " << each.join("; ") << " explains your answers equally well):\n";
    }
    for (const std::string& id : d.possibleMistakes) describe(id);
    for (const probes::RestitutionOf& r : d.restitution) {
        out << "restitution fitted to your collision answers: c = " << QString::number(r.c, 'g', 6) << " ("
            << QString::fromStdString(r.model) << ")\n";
    }
    if (d.firstDivergence) {
        const probes::Divergence& f = *d.firstDivergence;
        out << "first divergence from the right algorithm: probe " << d.divergenceProbe + 1 << " ("
            << QString::fromStdString(run.probes[d.divergenceProbe].name) << "), " << steps::stateName(f.step)
            << ", body " << f.body << ", " << QString::fromStdString(f.quantity) << ": expected " << numbers(f.expected)
            << ", yours " << numbers(f.given) << '\n';
    }
    out << "probes:\n";
    for (std::size_t p = 0; p < d.probes.size(); ++p) {
        out << "  " << p + 1 << ' ' << QString::fromStdString(run.probes[p].name) << "  ";
        if (d.probes[p].matchesRight) {
            out << "matches";
        } else {
            out << "differs";
            if (!d.probes[p].reproducedBy.empty()) {
                QStringList labels;
                for (const std::string& l : d.probes[p].reproducedBy) labels << QString::fromStdString(l);
                out << "; reproduced by " << labels.join(", ");
            }
        }
        out << "  (" << QString::fromStdString(run.probes[p].purpose) << ")\n";
    }
    writeTemplateText(out, run);
    out << "Numbers match within " << probes::kRelativeTolerance
        << " of the largest |value| of that quantity in the probe (float round-off matches).\n";
    if (!hasCollisionProbes(run)) out << "Not checked: the collision group (--probes collision or all).\n";
}

void writeDiagnoseCsv(QTextStream& out, const std::vector<DiagnoseRun>& runs)
{
    out << "program,probe,result,reproduced_by,step,body,quantity,expected,given,mistakes,restitution,"
           "template_tests_passed,message\n";
    for (const DiagnoseRun& run : runs) {
        const QString program = csvField(run.source);
        const probes::SimulatorDiagnosis& d = run.diagnosis;
        if (!run.failure.isEmpty()) {
            out << program << ",summary,bad-input,,,,,,,,,," << csvField(run.failure) << '\n';
            continue;
        }
        for (std::size_t p = 0; p < d.probes.size(); ++p) {
            const probes::ProbeOutcome& o = d.probes[p];
            out << program << ',' << QString::fromStdString(run.probes[p].name) << ','
                << (o.matchesRight ? "matches" : "differs") << ',' << csvField(joined(o.reproducedBy)) << ',';
            if (o.divergence) {
                out << o.divergence->step << ',' << o.divergence->body << ','
                    << QString::fromStdString(o.divergence->quantity) << ',' << joined(o.divergence->expected) << ','
                    << joined(o.divergence->given);
            } else {
                out << ",,,,";
            }
            out << ",,,,\n";
        }
        // the summary: the verdict, the first divergence of all, the mistakes, c, the template tests
        out << program << ",summary," << probes::verdictName(d.verdict) << ",,";
        if (d.firstDivergence) {
            const probes::Divergence& f = *d.firstDivergence;
            out << f.step << ',' << f.body << ',' << QString::fromStdString(run.probes[d.divergenceProbe].name) << '/'
                << QString::fromStdString(f.quantity) << ',' << joined(f.expected) << ',' << joined(f.given);
        } else {
            out << ",,,,";
        }
        out << ',' << csvField(joined(d.mistakes.empty() ? d.possibleMistakes : d.mistakes)) << ',';
        if (!d.restitution.empty()) out << QString::number(d.restitution.front().c, 'g', 6);
        out << ',';
        if (!run.templateTests.empty()) {
            int passed = 0;
            for (const TemplateTestResult& r : run.templateTests) passed += r.failure ? 0 : 1;
            out << passed << '/' << run.templateTests.size();
        }
        out << ",\n";
    }
}

} // namespace rbw
