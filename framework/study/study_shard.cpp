// study_shard: shards of a study and their merge (see study_shard.h).
#include "study_shard.h"

#include "study_table.h"

#include <map>
#include <set>
#include <stdexcept>

namespace sl {

void parseShard(const std::string& text, int& shard, int& shards) {
    const size_t slash = text.find('/');
    try {
        size_t a = 0, b = 0;
        if (slash == std::string::npos) throw std::invalid_argument(text);
        shard = std::stoi(text.substr(0, slash), &a);
        shards = std::stoi(text.substr(slash + 1), &b);
        if (a != slash || b != text.size() - slash - 1) throw std::invalid_argument(text);
    } catch (const std::logic_error&) {
        throw std::invalid_argument("--shard \"" + text + "\": expected K/N, e.g. 2/8");
    }
    if (shards < 1 || shard < 1 || shard > shards)
        throw std::invalid_argument("--shard \"" + text + "\": expected 1 <= K <= N");
}

std::vector<bool> shardRows(const std::vector<std::string>& digests, int shard, int shards) {
    std::map<std::string, int> group;  // map key -> its group's number
    int groups = 0;
    std::vector<bool> mine;
    for (const std::string& d : digests) {
        int g;
        if (d.empty()) g = groups++;
        else {
            auto it = group.find(d);
            g = it != group.end() ? it->second : (group[d] = groups++);
        }
        mine.push_back(g % shards == shard - 1);
    }
    return mine;
}

int mergeStudyShards(const std::vector<fs::path>& dirs, const fs::path& out) {
    fs::create_directories(out);
    const fs::path csv = out / "study.csv";
    std::set<std::string> have;
    for (const StudyRow& r : readStudyCsv(csv)) have.insert(r.key());
    int added = 0;
    for (const fs::path& dir : dirs) {
        if (!fs::exists(dir / "study.csv"))
            throw std::runtime_error((dir / "study.csv").string() + ": no study table to merge");
        for (const StudyRow& r : readStudyCsv(dir / "study.csv")) {
            if (!have.insert(r.key()).second) continue;
            appendStudyRow(csv, r);
            for (const std::string& f : {r.image, r.errorMap}) {
                fs::create_directories((out / f).parent_path());
                fs::copy_file(dir / f, out / f, fs::copy_options::overwrite_existing);
            }
            ++added;
        }
        // The truths' previews (the same in every shard of one sweep).
        if (fs::exists(dir / "truth"))
            fs::copy(dir / "truth", out / "truth",
                     fs::copy_options::recursive | fs::copy_options::skip_existing);
    }
    return added;
}

}  // namespace sl
