// study_shard: splitting a study over processes and joining it again. The rows of a sweep are
// independent but for the raw shadow maps they share (raw_map_key.h), so a shard takes whole
// groups of rows with one map key (a row that shares with none is its own group): group g, in
// the sweep's order, belongs to shard (g mod N) + 1. Each shard renders its groups' maps itself,
// so a shard's rows are the rows one process would write, the same images bit for bit. Merging
// copies each shard's rows and images into one folder; the study then writes the table in the
// sweep's order, so the merged CSV is the one process's but for what is measured (the cost
// columns) and what was reused where (`reused`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace sl {

namespace fs = std::filesystem;

// "K/N" with 1 <= K <= N; throws std::invalid_argument otherwise.
void parseShard(const std::string& text, int& shard, int& shards);

// For rows with these map-key digests (empty: shares with none), in the sweep's order: does
// row i belong to shard K of N?
std::vector<bool> shardRows(const std::vector<std::string>& mapDigests, int shard, int shards);

// Appends the rows of each DIR/study.csv not yet in out/study.csv, and copies their images
// (rows/, truth/) into `out`. Returns the number of rows added.
int mergeStudyShards(const std::vector<fs::path>& dirs, const fs::path& out);

}  // namespace sl
