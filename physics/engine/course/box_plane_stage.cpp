#include "physics/engine/course/box_plane_stage.h"

#include "physics/engine/course/box_plane.h"
#include "physics/engine/course/contact_response.h"
#include "physics/engine/scene_words.h"

namespace rbw {

void BoxPlaneStage::run(StepContext& ctx)
{
    const SceneDef& scene = ctx.scene;
    for (int p = 0; p < static_cast<int>(scene.planes.size()); ++p) {
        for (int b = 0; b < static_cast<int>(ctx.states.size()); ++b) {
            if (!ctx.movable[b]) continue;
            contacts_.clear();
            const int count = collideBoxPlane(poseOf(ctx, b), scene.planes[p], contacts_);
            if (count == 0) continue;
            if (scene.planeContacts == PlaneContactMode::Average) {
                // One impulse at the average of the corners (Napier assessment). The
                // resolution is the mode's scene word (a literal, so .data() ends in '\0').
                resolveContact(ctx, averageContact(contacts_, 0, contacts_.size()), b, -1, p,
                               sceneWord(PlaneContactMode::Average).data(), count);
            } else {
                // One impulse per corner, in turn, each seeing the velocities the
                // previous ones left.
                for (const ContactGeometry& g : contacts_) {
                    resolveContact(ctx, g, b, -1, p, sceneWord(PlaneContactMode::PerPoint).data(), 1);
                }
            }
        }
    }
}

} // namespace rbw
