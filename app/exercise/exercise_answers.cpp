#include "app/exercise/exercise_answers.h"

#include "app/exercise/answers_file.h"
#include "physics/engine/quantity_catalogue.h"

#include <type_traits>
#include <variant>

namespace rbw {

std::vector<Answer> exerciseAnswers(const GeneratedExercise& g)
{
    std::vector<Answer> answers;
    for (const TraceEntry& e : g.key) {
        Answer a;
        a.quantity = e.info->id;
        if (e.info->indexKind == IndexKind::Contact) {
            a.contact = e.index;
        } else {
            a.body = e.body;
            a.index = e.index;
        }
        std::visit(
            [&](const auto& v) {
                using T = std::decay_t<decltype(v)>;
                if constexpr (std::is_same_v<T, double>) {
                    a.value = {v};
                } else if constexpr (std::is_same_v<T, Vec3>) {
                    a.value = {v.x(), v.y(), v.z()};
                } else if constexpr (std::is_same_v<T, Quat>) {
                    a.value = {v.w(), v.x(), v.y(), v.z()};
                } else {
                    for (int r = 0; r < 3; ++r)
                        for (int c = 0; c < 3; ++c) a.value.push_back(v(r, c));
                }
            },
            e.value);
        answers.push_back(std::move(a));
    }
    return answers;
}

QByteArray exerciseAnswersJson(const GeneratedExercise& g)
{
    return answersToJson(exerciseAnswers(g), g.answerStep, *g.scene);
}

} // namespace rbw
