#include "app/derivation/standalone_html.h"

#include "app/derivation/derivation_page.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>

namespace rbw {

namespace {

bool readFile(const QString& path, QByteArray* out, QString* error)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error != nullptr) *error = QStringLiteral("cannot read %1: %2").arg(path, f.errorString());
        return false;
    }
    *out = f.readAll();
    return true;
}

} // namespace

QString inlinedKatexCss(const QString& katexDir, QString* error)
{
    const QDir dir(katexDir);
    QByteArray cssBytes;
    if (!readFile(dir.filePath(QStringLiteral("katex.min.css")), &cssBytes, error)) return QString();
    const QString css = QString::fromUtf8(cssBytes);

    // src:url(fonts/NAME.woff2) format('woff2'),url(...woff),url(...ttf) format(...);
    //   -> src:url(data:font/woff2;base64,...) format('woff2');
    static const QRegularExpression src(QStringLiteral(R"(src:\s*url\(\s*['"]?(fonts/[^)'"]+\.woff2)['"]?\s*\)[^;}]*)"));
    QString out;
    int last = 0;
    QRegularExpressionMatchIterator it = src.globalMatch(css);
    while (it.hasNext()) {
        const QRegularExpressionMatch m = it.next();
        QByteArray font;
        if (!readFile(dir.filePath(m.captured(1)), &font, error)) return QString();
        out += css.mid(last, m.capturedStart() - last);
        out += QStringLiteral("src:url(data:font/woff2;base64,%1) format('woff2')").arg(QString::fromLatin1(font.toBase64()));
        last = m.capturedEnd();
    }
    out += css.mid(last);
    if (last == 0) {
        if (error != nullptr) *error = QStringLiteral("no @font-face with a woff2 font in %1/katex.min.css").arg(katexDir);
        return QString();
    }
    return out;
}

QString standaloneDerivationHtml(const QString& renderedBodyHtml, const QString& title, const QString& katexDir,
                                 QString* error)
{
    const QString katexCss = inlinedKatexCss(katexDir, error);
    if (katexCss.isEmpty()) return QString();
    QString body = renderedBodyHtml;
    static const QRegularExpression script(QStringLiteral(R"(<script\b[^>]*>.*?</script\s*>)"),
                                           QRegularExpression::CaseInsensitiveOption |
                                               QRegularExpression::DotMatchesEverythingOption);
    body.remove(script);
    return QStringLiteral("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
                          "<title>%1</title>\n<style>%2</style>\n<style>%3</style>\n</head>\n<body>\n%4\n</body>\n</html>\n")
        .arg(htmlEscape(title), katexCss, derivationCss(), body);
}

} // namespace rbw
