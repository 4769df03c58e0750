#include "app/derivation/derivation_template.h"

#include "physics/engine/quantities.h"
#include "physics/engine/scene_words.h"

#include "app/derivation/trace_lookup.h"

#include <QRegularExpression>

namespace rbw {

namespace {

// "standard or course-template": the words of E for a message.
template <typename E>
QString wordsText()
{
    QStringList words;
    for (std::string_view w : sceneWords<E>()) words << QString::fromLatin1(w.data(), static_cast<qsizetype>(w.size()));
    return words.join(QStringLiteral(" or "));
}

const QStringList& sceneKeys()
{
    static const QStringList keys = {QStringLiteral("h"), QStringLiteral("mass"), QStringLiteral("size"),
                                     QStringLiteral("g")};
    return keys;
}

const QStringList& preIds()
{
    static const QStringList ids = {QLatin1String(q::linear_velocity.id), QLatin1String(q::angular_velocity.id),
                                    QLatin1String(q::angular_momentum.id)};
    return ids;
}

// Checks every {{...}} of a text line, including inline sections {{#kind}}..{{/kind}}.
void checkPlaceholders(const QString& text, const QString& where, QStringList& errors)
{
    QString openSection;
    int from = 0;
    while (true) {
        // A lone "}}" is ordinary LaTeX (\mathbf{v}_{\text{rel}}); only "{{" opens a placeholder.
        const int open = text.indexOf(QLatin1String("{{"), from);
        if (open < 0) break;
        const int close = text.indexOf(QLatin1String("}}"), open + 2);
        if (close < 0) {
            errors << where + QStringLiteral("'{{' without a closing '}}'");
            break;
        }
        const QString inside = text.mid(open + 2, close - open - 2).trimmed();
        from = close + 2;
        if (inside.startsWith(QLatin1Char('#')) || inside.startsWith(QLatin1Char('/'))) {
            const QString kind = inside.mid(1).trimmed();
            if (indexKindFromName(kind) == IndexKind::None) {
                errors << where + QStringLiteral("unknown section {{%1}}: use force, torque, probe, contact or correction")
                                      .arg(inside);
            } else if (inside.startsWith(QLatin1Char('#'))) {
                if (!openSection.isEmpty()) errors << where + QStringLiteral("sections {{#...}} cannot be nested");
                openSection = kind;
            } else if (openSection != kind) {
                errors << where + QStringLiteral("{{/%1}} does not close an open {{#%1}}").arg(kind);
            } else {
                openSection.clear();
            }
            continue;
        }
        Placeholder p;
        const QString problem = parsePlaceholder(inside, &p);
        if (!problem.isEmpty()) errors << where + problem;
    }
    if (!openSection.isEmpty()) errors << where + QStringLiteral("{{#%1}} is not closed on this line").arg(openSection);
}

QString checkCondition(const QString& cond)
{
    if (cond.isEmpty()) return QStringLiteral("@if needs a condition");
    // The words are the scene file's (physics/engine/scene_words.h).
    if (cond.startsWith(QLatin1String("convention="))) {
        const QString v = cond.mid(11);
        if (!sceneWordValue<InertiaConvention>(v.toStdString())) {
            return QStringLiteral("unknown convention '%1' (%2)").arg(v, wordsText<InertiaConvention>());
        }
        return QString();
    }
    if (cond.startsWith(QLatin1String("model="))) {
        const QString v = cond.mid(6);
        if (!sceneWordValue<ContactModel>(v.toStdString())) {
            return QStringLiteral("unknown contact model '%1' (%2)").arg(v, wordsText<ContactModel>());
        }
        return QString();
    }
    if (cond == QLatin1String("plane") || cond == QLatin1String("particle") ||
        cond.startsWith(QLatin1String("particle@"))) {
        return QString();
    }
    Placeholder p;
    const QString problem = parsePlaceholder(cond, &p);
    if (!problem.isEmpty()) return problem;
    if (!p.prefix.isEmpty()) return QStringLiteral("a condition is a quantity id, particle, plane or convention=...");
    return QString();
}

struct OpenBlock {
    TemplateNode node;
    bool inElse = false;
};

} // namespace

bool isMetaName(const QString& name)
{
    static const QStringList meta = {QStringLiteral("body"),       QStringLiteral("i"),
                                     QStringLiteral("A"),          QStringLiteral("B"),
                                     QStringLiteral("feature"),    QStringLiteral("resolution"),
                                     QStringLiteral("step"),       QStringLiteral("t"),
                                     QStringLiteral("integrator"), QStringLiteral("integrator_id")};
    return meta.contains(name);
}

QString parsePlaceholder(const QString& inside, Placeholder* out)
{
    // [prefix:]name[[index]][@body][.selector]
    static const QRegularExpression re(QStringLiteral(
        R"(^(?:([a-z]+):)?([A-Za-z_][A-Za-z0-9_]*)(?:\[(\d+)\])?(?:@([^\s.\[\]{}]+))?(?:\.([A-Za-z]+))?$)"));
    const QRegularExpressionMatch m = re.match(inside.trimmed());
    if (!m.hasMatch()) {
        return QStringLiteral("cannot read placeholder {{%1}}: expected {{[prefix:]id[[i]][@body][.x|.y|.z|.T]}}")
            .arg(inside);
    }
    Placeholder p;
    p.prefix = m.captured(1);
    p.name = m.captured(2);
    p.index = m.captured(3).isEmpty() ? -1 : m.captured(3).toInt();
    p.body = m.captured(4);
    p.selector = m.captured(5);
    static const QStringList prefixes = {QString(), QStringLiteral("symbol"), QStringLiteral("formula"),
                                         QStringLiteral("unit"), QStringLiteral("scene"), QStringLiteral("pre"),
                                         QStringLiteral("start")};
    if (!prefixes.contains(p.prefix)) {
        return QStringLiteral("unknown prefix '%1:' in {{%2}} (symbol, formula, unit, scene, pre or start)")
            .arg(p.prefix, inside);
    }
    if (!p.selector.isEmpty() && p.selector != QLatin1String("x") && p.selector != QLatin1String("y") &&
        p.selector != QLatin1String("z") && p.selector != QLatin1String("T")) {
        return QStringLiteral("unknown selector '.%1' in {{%2}} (.x, .y, .z or .T)").arg(p.selector, inside);
    }
    if (p.prefix == QLatin1String("scene")) {
        if (!sceneKeys().contains(p.name)) {
            return QStringLiteral("unknown scene value '%1' in {{%2}} (h, mass, size or g)").arg(p.name, inside);
        }
    } else if (p.prefix == QLatin1String("pre")) {
        if (!preIds().contains(p.name)) {
            return QStringLiteral("{{pre:...}} works for linear_velocity, angular_velocity and angular_momentum, not '%1'")
                .arg(p.name);
        }
    } else if (p.prefix == QLatin1String("start")) {
        if (!hasStartValue(p.name.toStdString())) {
            return QStringLiteral("{{start:...}} works for the state quantities position, linear_velocity, orientation, "
                                  "angular_momentum, rotation_matrix, inverse_inertia_world, angular_velocity, "
                                  "probe_position and point_velocity, not '%1'")
                .arg(p.name);
        }
    } else if (p.prefix.isEmpty() && isMetaName(p.name)) {
        // meta text
    } else if (findQuantity(p.name.toStdString()) == nullptr) {
        return QStringLiteral("unknown quantity '%1' in {{%2}} (rbw quantities lists the ids)")
            .arg(p.name, inside);
    }
    *out = p;
    return QString();
}

TemplateParseResult parseDerivationTemplate(const QString& text, const QString& label)
{
    TemplateParseResult result;
    std::vector<OpenBlock> stack;
    std::vector<TemplateNode> top;
    auto target = [&]() -> std::vector<TemplateNode>& {
        if (stack.empty()) return top;
        OpenBlock& b = stack.back();
        return b.inElse ? b.node.elseChildren : b.node.children;
    };
    // Paragraph and list lines gather until a blank line or another kind of line.
    auto lastOpen = [&](TemplateNode::Kind kind) -> TemplateNode* {
        std::vector<TemplateNode>& t = target();
        if (!t.empty() && t.back().kind == kind && !t.back().closed) return &t.back();
        return nullptr;
    };
    auto closeParagraphs = [&]() {
        std::vector<TemplateNode>& t = target();
        if (!t.empty() && (t.back().kind == TemplateNode::Kind::Paragraph || t.back().kind == TemplateNode::Kind::List)) {
            t.back().closed = true;
        }
    };

    const QStringList lines = text.split(QLatin1Char('\n'));
    for (int i = 0; i < lines.size(); ++i) {
        const int lineNo = i + 1;
        const QString where = QStringLiteral("%1:%2: ").arg(label).arg(lineNo);
        QString line = lines[i];
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
        const QString trimmed = line.trimmed();

        if (trimmed.isEmpty()) {
            closeParagraphs();
            continue;
        }
        if (trimmed.startsWith(QLatin1String("<!--"))) {
            if (!trimmed.endsWith(QLatin1String("-->"))) {
                result.errors << where + QStringLiteral("a comment <!-- ... --> must end on the same line");
            }
            continue;
        }
        if (trimmed.startsWith(QLatin1Char('@'))) {
            closeParagraphs();
            const int space = trimmed.indexOf(QLatin1Char(' '));
            const QString word = space < 0 ? trimmed : trimmed.left(space);
            const QString arg = space < 0 ? QString() : trimmed.mid(space + 1).trimmed();
            if (word == QLatin1String("@foreach")) {
                if (indexKindFromName(arg) == IndexKind::None && arg != QLatin1String("body")) {
                    result.errors << where + QStringLiteral("@foreach needs body, force, torque, probe, contact or correction, got '%1'").arg(arg);
                }
                TemplateNode n;
                n.kind = TemplateNode::Kind::Loop;
                n.line = lineNo;
                n.text = arg;
                stack.push_back(OpenBlock{n, false});
            } else if (word == QLatin1String("@body")) {
                if (arg.isEmpty()) result.errors << where + QStringLiteral("@body needs a body name");
                TemplateNode n;
                n.kind = TemplateNode::Kind::Body;
                n.line = lineNo;
                n.text = arg;
                stack.push_back(OpenBlock{n, false});
            } else if (word == QLatin1String("@if") || word == QLatin1String("@ifnot")) {
                const QString problem = checkCondition(arg);
                if (!problem.isEmpty()) result.errors << where + problem;
                TemplateNode n;
                n.kind = TemplateNode::Kind::If;
                n.line = lineNo;
                n.text = arg;
                n.negate = word == QLatin1String("@ifnot");
                stack.push_back(OpenBlock{n, false});
            } else if (word == QLatin1String("@integration") || word == QLatin1String("@iterations")) {
                if (!arg.isEmpty()) result.errors << where + QStringLiteral("%1 takes no argument").arg(word);
                TemplateNode n;
                n.kind = word == QLatin1String("@integration") ? TemplateNode::Kind::Integration
                                                               : TemplateNode::Kind::Iterations;
                n.line = lineNo;
                target().push_back(std::move(n));
            } else if (word == QLatin1String("@else")) {
                if (stack.empty() || stack.back().node.kind == TemplateNode::Kind::Body) {
                    result.errors << where + QStringLiteral("@else outside an @if or @foreach block");
                } else if (stack.back().inElse) {
                    result.errors << where + QStringLiteral("second @else in the block opened on line %1")
                                                 .arg(stack.back().node.line);
                } else {
                    stack.back().inElse = true;
                }
            } else if (word == QLatin1String("@end")) {
                if (stack.empty()) {
                    result.errors << where + QStringLiteral("@end without an opening @foreach, @body or @if");
                } else {
                    TemplateNode done = std::move(stack.back().node);
                    stack.pop_back();
                    target().push_back(std::move(done));
                }
            } else {
                result.errors << where + QStringLiteral("unknown directive '%1' (@foreach, @body, @if, @ifnot, @else, @end, @integration, @iterations)").arg(word);
            }
            continue;
        }

        checkPlaceholders(trimmed, where, result.errors);
        if (trimmed.startsWith(QLatin1Char('#'))) {
            closeParagraphs();
            int level = 0;
            while (level < trimmed.size() && trimmed[level] == QLatin1Char('#')) ++level;
            if (level > 3 || level >= trimmed.size() || trimmed[level] != QLatin1Char(' ')) {
                result.errors << where + QStringLiteral("a heading is '# ', '## ' or '### ' followed by text");
                continue;
            }
            TemplateNode n;
            n.kind = TemplateNode::Kind::Heading;
            n.line = lineNo;
            n.level = level;
            n.text = trimmed.mid(level + 1).trimmed();
            target().push_back(std::move(n));
        } else if (trimmed.startsWith(QLatin1String("= ")) || trimmed == QLatin1String("=")) {
            closeParagraphs();
            QStringList cells = trimmed.mid(1).split(QLatin1String("&&"));
            for (QString& c : cells) c = c.trimmed();
            if (cells.size() > 3) {
                result.errors << where + QStringLiteral("a row has at most 3 cells (formula && substituted && result), got %1")
                                             .arg(cells.size());
                continue;
            }
            if (cells.first().isEmpty()) {
                result.errors << where + QStringLiteral("a row needs a formula in its first cell");
                continue;
            }
            TemplateNode n;
            n.kind = TemplateNode::Kind::Row;
            n.line = lineNo;
            n.items = cells;
            target().push_back(std::move(n));
        } else if (trimmed.startsWith(QLatin1String("$$"))) {
            closeParagraphs();
            if (trimmed.size() < 4 || !trimmed.endsWith(QLatin1String("$$"))) {
                result.errors << where + QStringLiteral("display math must open and close with $$ on the same line");
                continue;
            }
            TemplateNode n;
            n.kind = TemplateNode::Kind::DisplayMath;
            n.line = lineNo;
            n.text = trimmed.mid(2, trimmed.size() - 4).trimmed();
            target().push_back(std::move(n));
        } else if (trimmed.startsWith(QLatin1String("- "))) {
            if (trimmed.count(QLatin1Char('$')) % 2 != 0) {
                result.errors << where + QStringLiteral("unbalanced $: inline math is $...$ on one line");
            }
            if (TemplateNode* list = lastOpen(TemplateNode::Kind::List)) {
                list->items << trimmed.mid(2);
            } else {
                closeParagraphs();
                TemplateNode n;
                n.kind = TemplateNode::Kind::List;
                n.line = lineNo;
                n.items << trimmed.mid(2);
                target().push_back(std::move(n));
            }
        } else {
            if (trimmed.count(QLatin1Char('$')) % 2 != 0) {
                result.errors << where + QStringLiteral("unbalanced $: inline math is $...$ on one line");
            }
            if (TemplateNode* para = lastOpen(TemplateNode::Kind::Paragraph)) {
                para->text += QLatin1Char(' ') + trimmed;
            } else {
                closeParagraphs();
                TemplateNode n;
                n.kind = TemplateNode::Kind::Paragraph;
                n.line = lineNo;
                n.text = trimmed;
                target().push_back(std::move(n));
            }
        }
    }
    for (const OpenBlock& b : stack) {
        result.errors << QStringLiteral("%1:%2: this block is never closed: add @end").arg(label).arg(b.node.line);
    }
    if (result.errors.isEmpty()) {
        result.parsed = DerivationTemplate{label, std::move(top)};
    }
    return result;
}

} // namespace rbw
