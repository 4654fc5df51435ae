// raw_map_cache: see raw_map_cache.h.
#include "raw_map_cache.h"

namespace sl {

void RawMapCache::expect(const std::string& digest) {
    if (!digest.empty()) ++remaining_[digest];
}

const SharedRawMap* RawMapCache::find(const std::string& digest) const {
    auto it = maps_.find(digest);
    return it == maps_.end() ? nullptr : &it->second;
}

void RawMapCache::keep(const std::string& digest, SharedRawMap map) {
    auto it = remaining_.find(digest);
    if (digest.empty() || it == remaining_.end() || it->second <= 1) return;  // nobody after
    maps_[digest] = std::move(map);
    ++kept_;
}

void RawMapCache::done(const std::string& digest) {
    auto it = remaining_.find(digest);
    if (it == remaining_.end()) return;
    if (--it->second <= 0) {
        remaining_.erase(it);
        maps_.erase(digest);
    }
}

}  // namespace sl
