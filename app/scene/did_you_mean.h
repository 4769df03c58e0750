// "Did you mean": the allowed key nearest to an unknown one (internal to app/scene).
#pragma once

#include <QString>
#include <QStringList>

namespace rbw::scenefile {

// Levenshtein distance: insertions, deletions and substitutions of one character.
int editDistance(const QString& a, const QString& b);

// The allowed key at the smallest edit distance from `key`, if that distance is at
// most 2 (the first such key in `allowed` on a tie); empty if none is that near.
QString nearestKey(const QString& key, const QStringList& allowed);

} // namespace rbw::scenefile
