#include "app/derivation/integrator_sections.h"

#include "physics/engine/integrator_registry.h"

#include <QFile>
#include <QMutex>
#include <QMutexLocker>

#include <map>
#include <memory>

namespace rbw {

namespace {

std::unique_ptr<IntegratorSection> loadSection(const QString& fileName)
{
    auto section = std::make_unique<IntegratorSection>();
    section->label = QStringLiteral("app/derivation/integrators/%1").arg(fileName);
    QFile file(QStringLiteral(":/derivation/integrators/%1").arg(fileName));
    if (!file.open(QIODevice::ReadOnly)) {
        section->errors << QStringLiteral("%1: missing from the program's resources").arg(section->label);
        return section;
    }
    TemplateParseResult parsed = parseDerivationTemplate(QString::fromUtf8(file.readAll()), section->label);
    if (!parsed.ok()) {
        section->errors = parsed.errors;
        return section;
    }
    section->nodes = std::move(parsed.parsed->nodes);
    return section;
}

} // namespace

std::vector<const IntegratorSection*> integratorSections(const QString& integratorName)
{
    static QMutex mutex;
    static std::map<QString, std::unique_ptr<IntegratorSection>> cache;
    const QMutexLocker lock(&mutex);
    auto get = [&](const QString& fileName) -> const IntegratorSection* {
        std::unique_ptr<IntegratorSection>& slot = cache[fileName];
        if (!slot) slot = loadSection(fileName);
        return slot.get();
    };

    const std::unique_ptr<Integrator> integrator = makeIntegrator(integratorName.toStdString());
    if (!integrator) {
        std::unique_ptr<IntegratorSection>& slot = cache[QStringLiteral("unknown:") + integratorName];
        if (!slot) {
            slot = std::make_unique<IntegratorSection>();
            slot->errors << QStringLiteral("no derivation section for the integrator '%1' (known: %2)")
                                .arg(integratorName, QString::fromStdString(integratorNames()));
        }
        return {slot.get()};
    }
    const bool fromMatrix = integrator->derivedFrom() == Integrator::Derived::FromMatrix;
    return {get(integratorName + QStringLiteral(".md")),
            get(fromMatrix ? QStringLiteral("derived-from-matrix.md") : QStringLiteral("derived.md"))};
}

} // namespace rbw
