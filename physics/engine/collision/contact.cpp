#include "physics/engine/collision/contact.h"

namespace rbw {

const char* featureName(ContactFeature f)
{
    switch (f) {
    case ContactFeature::VertexFace: return "vertex-face";
    case ContactFeature::FaceVertex: return "face-vertex";
    case ContactFeature::EdgeEdge: return "edge-edge";
    case ContactFeature::VertexPlane: return "vertex-plane";
    }
    return "?";
}

} // namespace rbw
