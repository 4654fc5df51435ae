// depth_ladder: the moments stage's relativeDepth ladder (see the header).
#include "depth_ladder.h"

#include <algorithm>

namespace sl {

const std::vector<glm::vec3>& relativeDepthLadder() {
    static const std::vector<glm::vec3> rows = [] {
        std::vector<glm::vec3> r;
        // Ranges like the public scenes' (auto ranges of a few units, an explicit [2, 50]) and
        // a narrow one; 25 depths from half a range in front of near to half a range behind far.
        for (glm::vec2 range : {glm::vec2(1.0f, 9.0f), glm::vec2(2.0f, 50.0f), glm::vec2(10.0f, 10.5f)}) {
            const float span = range.y - range.x;
            for (int i = 0; i <= 24; ++i)
                r.push_back({range.x + span * (-0.5f + 2.0f * float(i) / 24.0f), range.x, range.y});
        }
        return r;
    }();
    return rows;
}

glm::dvec4 exactLadderMoments(glm::vec3 row) {
    const double z = std::clamp((double(row.x) - row.y) / (double(row.z) - row.y), 0.0, 1.0);
    return {z, z * z, z * z * z, z * z * z * z};
}

Image depthLadderExpected() {
    const auto& rows = relativeDepthLadder();
    Image img(int(rows.size()), 1, 4);
    for (size_t i = 0; i < rows.size(); ++i) {
        const glm::dvec4 m = exactLadderMoments(rows[i]);
        for (int c = 0; c < 4; ++c) img.at(int(i), 0, c) = float(m[c]);
    }
    return img;
}

Image depthLadderImage(const std::vector<glm::vec4>& moments) {
    Image img(int(moments.size()), 1, 4);
    for (size_t i = 0; i < moments.size(); ++i)
        for (int c = 0; c < 4; ++c) img.at(int(i), 0, c) = moments[i][c];
    return img;
}

bool depthLadderStub(const Image& ladder) {
    if (ladder.width == 0) return false;
    for (int i = 0; i < ladder.width; ++i) {
        const bool b1 = ladder.at(i, 0, 0) == -1.0f && ladder.at(i, 0, 2) == -1.0f;
        const float even = ladder.at(i, 0, 1);
        if (!b1 || ladder.at(i, 0, 3) != even || (even != 1.0f && even != -1.0f)) return false;
    }
    return true;
}

}  // namespace sl
