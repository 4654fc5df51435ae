// raw_map_cache: the study's shared raw shadow maps. A sweep first counts how many of its rows
// will use each raw-map key (raw_map_key.h); the first of them renders the map (its shadow pass
// runs in every frame it times) and leaves the raw layers here with its shadow-pass times; the
// others light with those layers, their shadow pass skipped, and report the times measured
// when the map was rendered. A map is dropped with its last use, so that a sweep holds only the
// maps still to be read (at most a few 2048² maps at once).
#pragma once

#include "renderer.h"

#include <map>
#include <string>
#include <vector>

namespace sl {

struct SharedRawMap {
    RawShadowMap map;                  // the light's raw map, as read back (renderer.h)
    std::string sourceRow;             // the study row (StudyRow::key) that rendered it
    // That row's shadow-pass times in each timed frame (one per shadow pass of the light), ms.
    std::vector<std::vector<double>> shadowMillis;
};

class RawMapCache {
public:
    // One more row will ask for `digest` (call for every row before the sweep starts).
    void expect(const std::string& digest);
    // The map, if a row has rendered it and another is still to use it; else null.
    const SharedRawMap* find(const std::string& digest) const;
    // A row has rendered the map: kept if some later row expects it.
    void keep(const std::string& digest, SharedRawMap map);
    // A row is done with `digest` (rendered or shared): the map goes with the last use.
    void done(const std::string& digest);

    int kept() const { return kept_; }        // maps rendered and kept for later rows

private:
    std::map<std::string, int> remaining_;
    std::map<std::string, SharedRawMap> maps_;
    int kept_ = 0;
};

}  // namespace sl
