// The penalty cross-check must be able to fail. Both codes solve the penalised problem at eps = 1e-3
// (the plate below R over the whole disk) and 1e-4 (the curve w = R inside it, so the rule follows
// the kink) with the penalty integrated over the true disk (D30), each refined to its limit with a
// bar; the program must say "agree" when the scenes are the same and "DIFFER" (exit 3, a check
// missed) when ours has the obstacle raised by a relative 1e-4, ten times the resolution these small
// meshes give (about 1e-5; the report says so). FreeFEM on 8 to 32 cells per quarter circle, ours on
// h = 1/32 to 1/128: about twenty seconds a run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "exit_codes.hpp"
#include "run_program.hpp"
#include "scratch.hpp"
#include "words.hpp"
#include "words_file.hpp"

using namespace plate;

namespace {
const Scratch& scratch() {
  static const Scratch s("crosscheck_penalty");
  return s;
}

struct Outcome {
  Captured run;
  std::string report;
};

// The fixed-eps part alone, our obstacle's height times 1 + perturb.
Outcome fixed_eps(const std::string& tag, const std::string& perturb) {
  const std::string out = scratch().path("out_" + tag);
  std::filesystem::create_directories(out);
  const std::string cmd = "'" BUILD_DIR "/crosscheck_penalty' --parts eps --eps 1e-3,1e-4 --grids 32,64,128 --meshes 2,4,8"
                          " --results '" PLATE_SOURCE_DIR "/results' --reference '" PLATE_SOURCE_DIR "/reference'"
                          " --out '" + out + "' --work '" + scratch().path("work_" + tag) + "' --perturb " + perturb + " 2>&1";
  Outcome o{run_captured(cmd), ""};
  std::ifstream in(out + "/crosscheck_penalty.md");
  std::stringstream ss;
  ss << in.rdbuf();
  o.report = Words(PLATE_SOURCE_DIR "/reports/words.md").render(ss.str());  // the report as a reader reads it
  return o;
}
}  // namespace

TEST(PenaltyCrossCheck, AgreesOnTheSameSceneAndSaysDifferWhenOursIsRaisedByOneInTenThousand) {
  const Outcome same = fixed_eps("same", "0");
  EXPECT_EQ(same.run.status, 0) << same.run.output;
  EXPECT_EQ(same.report.find("DIFFER"), std::string::npos) << same.report;
  EXPECT_NE(same.report.find("Verdict: every check agrees."), std::string::npos) << same.report;

  const Outcome raised = fixed_eps("raised", "1e-4");
  EXPECT_EQ(raised.run.status, kNotConverged) << raised.run.output;
  // Every row, max w and the force at each eps, must see it: homogeneity moves each by the same
  // relative 1e-4.
  size_t rows = 0;
  for (size_t at = raised.report.find("**DIFFER**"); at != std::string::npos; at = raised.report.find("**DIFFER**", at + 1)) ++rows;
  EXPECT_EQ(rows, 4u) << raised.report;
  EXPECT_NE(raised.report.find("some checks FAIL"), std::string::npos) << raised.report;
}

TEST(PenaltyCrossCheck, RefusesBadOptionsByName) {
  const struct {
    std::string args, names;
  } cases[] = {
      {"--eps 1e-3,1e-2", "--eps"},        {"--eps nan", "--eps"},         {"--eps 0.5", "--eps"},
      {"--grids 32,64", "--grids"},        {"--grids 32,63,128", "--grids"}, {"--grids 64,32,128", "--grids"},
      {"--meshes 1,2", "--meshes"},        {"--meshes 0,1,2", "--meshes"}, {"--meshes 1,2,64", "--meshes"},
      {"--perturb nan", "--perturb"},      {"--perturb 0.7", "--perturb"}, {"--parts eps,tables", "--parts"},
      // Fig. 2 is judged by the limits at its eps: without them it would have no judge.
      {"--parts fig2", "--parts"},         {"--parts eps,fig2 --eps 1e-3,1e-4", "--parts"},
  };
  for (const auto& c : cases) {
    const Captured r = run_captured("'" BUILD_DIR "/crosscheck_penalty' " + c.args + " --out '" + scratch().path("bad") + "' 2>&1");
    EXPECT_EQ(r.status, kBadInput) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.names), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(scratch().path("bad")));
}
