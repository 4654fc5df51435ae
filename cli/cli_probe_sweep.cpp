// cli_probe_sweep: `shadowlab probe msm --sweep` — the property sweep of docs/numerics.md on any
// solution's momentShadowIntensity (msm_sweep.h): 10⁶ generated cases in one dispatch, checked
// against bounds that need no 4MSM solver; the summary on stdout, the failing cases to --out.
#include "cli_probe.h"

#include "exit_codes.h"
#include "gl_context.h"
#include "msm_sweep.h"
#include "probe.h"
#include "probe_csv.h"
#include "stage_functions.h"

#include <chrono>
#include <cstdio>
#include <iostream>

namespace sl::cli {

int runMsmSweep(const ProbeArgs& a, const std::string& backend) {
    if (!a.input.empty() || !a.generate.empty())
        throw std::invalid_argument("probe msm --sweep generates its own cases: no --input or --generate");
    const auto start = std::chrono::steady_clock::now();
    const MsmSweepCases cases = generateMsmSweep(a.vectors, a.seed);
    auto context = createContext(parseBackendKind(backend));
    const ShaderLibrary library = ShaderLibrary::forSolution(resolveSolution(a.solution), repoRoot());
    const std::string file = library.displayPath(library.resolve("msm.glsl"));
    const std::vector<float> g = probeMomentShadowIntensity(library, cases.b, cases.zf, a.alpha);
    const MsmSweepReport report = checkMsmSweep(cases, g, a.alpha);
    std::cout << file << ": momentShadowIntensity, seed " << a.seed << "\n"
              << msmSweepSummary(report, cases, g, a.alpha);
    if (report.stub)
        std::cout << stubNoteText(file, StageFunction::MomentShadowIntensity) << "\n";
    if (!a.out.empty()) {
        Table t;
        t.header = {"check", "m1", "m2", "m3", "m4", "zf", "G", "bound"};
        for (const auto& p : report.problems) {
            const glm::vec4 b = cases.b[p.index];
            t.rows.push_back({p.what, csvNumber(b.x), csvNumber(b.y), csvNumber(b.z), csvNumber(b.w),
                              csvNumber(cases.zf[p.index]), csvNumber(g[p.index]), csvNumber(p.bound)});
        }
        sanitizeFields(t);
        writeCsv(a.out, t, {}, {});
        std::cout << "failing cases: " << a.out << " (" << t.rows.size() << " rows)\n";
    }
    std::printf("time: %.2f s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return Ok;
}

}  // namespace sl::cli
