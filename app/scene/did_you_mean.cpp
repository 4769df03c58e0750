#include "app/scene/did_you_mean.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace rbw::scenefile {

int editDistance(const QString& a, const QString& b)
{
    std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
    for (int j = 0; j <= b.size(); ++j) prev[j] = j;
    for (int i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (int j = 1; j <= b.size(); ++j) {
            const int subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

QString nearestKey(const QString& key, const QStringList& allowed)
{
    QString best;
    int bestDistance = 3;
    for (const QString& k : allowed) {
        // The distance is at least the difference in length: a long key is never
        // compared letter by letter (a 50 MB key took 15 s).
        if (std::abs(key.size() - k.size()) >= bestDistance) {
            continue;
        }
        const int d = editDistance(key, k);
        if (d < bestDistance) {
            bestDistance = d;
            best = k;
        }
    }
    return best;
}

} // namespace rbw::scenefile
