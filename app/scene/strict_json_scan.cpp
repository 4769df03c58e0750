#include "app/scene/strict_json_scan.h"

#include "app/scene/scene_fields.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rbw::scenefile {
namespace {

// 1-based line and column of a byte offset.
std::pair<qsizetype, qsizetype> lineColumn(const QByteArray& text, qsizetype offset)
{
    qsizetype line = 1;
    qsizetype column = 1;
    for (qsizetype i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return {line, column};
}

bool isBareChar(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '+' || c == '-' ||
           c == '.';
}

// What a bare word that QJsonDocument refused stands for, as a reason; empty if it is
// something else (a typo such as `tru`), which QJsonDocument's own error describes.
QString nonFiniteReason(const QByteArray& token)
{
    const QByteArray word = token.toLower();
    if (word == "nan" || word == "-nan" || word == "+nan" || word == "infinity" || word == "-infinity" ||
        word == "+infinity" || word == "inf" || word == "-inf" || word == "+inf") {
        return QStringLiteral("must be a finite number, got %1 (not a JSON number: JSON has no literal for a "
                              "value that is not finite)")
            .arg(QString::fromLatin1(token));
    }
    bool ok = false;
    token.toDouble(&ok);   // as QJsonDocument reads a number
    if (ok || token.isEmpty()) {
        return {};
    }
    // A decimal number out of a double's range: read as a long double (locale-free),
    // whose range reaches 1e4932, it shows which side; beyond that, the exponent's sign.
    // libstdc++ 12's from_chars for long double runs strlen over its input for a word
    // that starts like "-Inf" (a fuzz finding, docs/reliability.md): give it its own
    // '\0'-terminated copy, whatever the token's buffer holds after its end.
    const std::string text(token.constData(), static_cast<std::size_t>(token.size()));
    long double x = 0.0L;
    const char* const last = text.data() + text.size();
    const std::from_chars_result r = std::from_chars(text.data(), last, x);
    if (r.ptr != last || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range)) {
        return {};   // not a number at all: QJsonDocument's message
    }
    const bool tooLarge = r.ec == std::errc() ? std::abs(x) > std::numeric_limits<double>::max()
                                              : !word.contains("e-");
    if (tooLarge) {
        return QStringLiteral("must be a finite number, got %1 (too large for a double, whose largest value is "
                              "1.8e308)")
            .arg(QString::fromLatin1(token));
    }
    return QStringLiteral("must be a number a double can hold, got %1 (nearer to 0 than any double but 0; "
                          "write 0 if 0 is meant)")
        .arg(QString::fromLatin1(token));
}

} // namespace

QString textPosition(const QByteArray& text, qsizetype offset)
{
    const auto [line, column] = lineColumn(text, offset);
    return QStringLiteral("line %1, column %2").arg(line).arg(column);
}

std::optional<RawFinding> scanParsed(const QByteArray& json, const QJsonParseError& error)
{
    const bool parsed = error.error == QJsonParseError::NoError;
    const bool badWord = error.error == QJsonParseError::IllegalNumber || error.error == QJsonParseError::IllegalValue;
    if (!parsed && !badWord) return std::nullopt;
    // QJsonDocument's error offset lies in or after the token it stopped at.
    return scanJson(json, parsed ? json.size() : error.offset + 1, badWord);
}

std::optional<RawFinding> scanJson(const QByteArray& json, qsizetype end, bool checkNumbers)
{
    struct Frame {
        bool object = false;
        std::string key;                                      // object: the current member's key
        qsizetype index = 0;                                  // array: the current element
        bool expectKey = true;                                // object: the next string is a key
        std::unordered_map<std::string, qsizetype> keys = {}; // object: each key's first offset
    };
    std::vector<Frame> stack;
    auto path = [&stack] {
        QString p;
        for (const Frame& f : stack) {
            if (f.object) {
                p += (p.isEmpty() ? QString() : QStringLiteral(".")) + shown(QString::fromStdString(f.key));
            } else {
                p += QStringLiteral("[%1]").arg(f.index);
            }
        }
        return p;
    };
    const char* text = json.constData();
    const qsizetype size = json.size();
    qsizetype i = json.startsWith("\xef\xbb\xbf") ? 3 : 0;   // a UTF-8 byte order mark, which QJsonDocument skips
    while (i < end && i < size) {
        const char c = text[i];
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ':') {
            ++i;
        } else if (c == '{' || c == '[') {
            Frame frame;
            frame.object = c == '{';
            stack.push_back(std::move(frame));
            ++i;
        } else if (c == '}' || c == ']') {
            if (stack.empty()) return std::nullopt;
            stack.pop_back();
            ++i;
        } else if (c == ',') {
            if (stack.empty()) return std::nullopt;
            Frame& f = stack.back();
            if (f.object) {
                f.expectKey = true;
            } else {
                ++f.index;
            }
            ++i;
        } else if (c == '"') {
            qsizetype j = i + 1;
            bool escaped = false;
            while (j < size && text[j] != '"') {
                escaped = escaped || text[j] == '\\';
                j += text[j] == '\\' ? 2 : 1;
            }
            if (j >= size) return std::nullopt;
            if (!stack.empty() && stack.back().object && stack.back().expectKey) {
                Frame& f = stack.back();
                f.expectKey = false;
                // Unescaped by QJsonDocument itself, so "m\u0061ss" is "mass" here too.
                f.key = escaped ? QJsonDocument::fromJson("[" + json.mid(i, j + 1 - i) + "]")
                                      .array()
                                      .at(0)
                                      .toString()
                                      .toStdString()
                                : std::string(text + i + 1, text + j);
                const auto [first, isNew] = f.keys.emplace(f.key, i);
                if (!isNew) {
                    return RawFinding{path(),
                                      QStringLiteral("duplicate key \"%1\" (first at %2, again at %3); a key may "
                                                     "appear only once in an object")
                                          .arg(shown(QString::fromStdString(f.key)), textPosition(json, first->second),
                                               textPosition(json, i))};
                }
            }
            i = j + 1;
        } else if (isBareChar(c)) {
            qsizetype j = i;
            while (j < size && isBareChar(text[j])) ++j;
            if (checkNumbers) {
                const QString reason = nonFiniteReason(json.mid(i, j - i));
                if (!reason.isEmpty()) {
                    return RawFinding{path(), reason};
                }
            }
            i = j;
        } else {
            return std::nullopt;   // not JSON: QJsonDocument's error says where
        }
    }
    return std::nullopt;
}

} // namespace rbw::scenefile
