// study_cost: the study's cost axis (see study_cost.h).
#include "study_cost.h"

#include "cost_clock.h"
#include "gl_api.h"

#include <algorithm>

namespace sl {

CostStats costStats(const std::vector<double>& values) {
    CostStats s;
    if (values.empty()) return s;
    std::vector<double> v = values;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    s.min = v.front();
    s.max = v.back();
    s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    return s;
}

CopyYardstick::CopyYardstick(Renderer& r)
    : renderer_(r), src_(Texture::create(1024, 1024, GL_RGBA32F)),
      dst_(Texture::create(1024, 1024, GL_RGBA32F)) {
    renderer_.copyPass(src_, dst_);  // compile, fault the textures in
    gl::Finish();
}

double CopyYardstick::measureOnce() {
    gl::Finish();
    costBegin();
    renderer_.copyPass(src_, dst_);
    gl::Finish();
    return costEnd();
}

}  // namespace sl
