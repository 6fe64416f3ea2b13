// ochre-slurm on a real Slurm (label `slurm`): a one-node cluster (tools/scripts/one_node_cluster.sh: munge,
// slurmctld and slurmd on 127.0.0.1, state in a temporary folder, stopped by PID) renders the Cornell box as
// a 4-task job array whose merge job writes the image of a single-process render, bit for bit; a cancelled
// task is reported by the merge and re-submitted alone; two frames of a flicker sequence in two parts each,
// one array, merge to the bits of `ochre render --frames 2`. Skips with a message when Slurm is not installed
// (tools/setup.sh installs it) or the cluster cannot start here.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>

#include "cli/cli_runner.h"
#include "cli/exr_bits.h"
#include "cli/torch_scene.h"
#include "support/test_paths.h"

namespace ochre::test::slurm_test {
namespace {

namespace fs = std::filesystem;

// Runs a shell command; its exit code and combined output.
CommandResult shell(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  for (size_t n; (n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
    result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string quoted(const fs::path& path) {
  return fmt::format("'{}'", path.string());
}

class Slurm : public ::testing::Test {
 protected:
  void SetUp() override {
    const CommandResult check = shell(cluster_script() + " check");
    if (check.exit_code != 0) GTEST_SKIP() << "Slurm cannot run here: " << check.output;
    char dir_template[] = "/tmp/ochre-slurm.XXXXXX";  // short: the munge socket path has a length limit
    ASSERT_NE(::mkdtemp(dir_template), nullptr);
    cluster_dir = dir_template;
    const CommandResult start = shell(cluster("start"));
    if (start.exit_code != 0) {
      cluster_dir.clear();  // the script stopped what it started
      GTEST_SKIP() << "the one-node Slurm cluster did not start: " << start.output;
    }
    ::setenv("SLURM_CONF", (cluster_dir / "etc/slurm.conf").c_str(), 1);
    ASSERT_EQ(run_ochre("render " + quoted(source_dir() / kScene) + " " + kSettings +
                            " -o single.exr --png single.png -q",
                        work)
                  .exit_code,
              0);
  }
  void TearDown() override {
    if (cluster_dir.empty()) return;
    if (HasFailure()) {
      ::setenv("SLURM_ONE_NODE_KEEP", "1", 1);  // the daemons' logs stay for a look
      std::cerr << "cluster folder kept: " << cluster_dir << "\n";
    }
    const CommandResult stop = shell(cluster("stop"));
    EXPECT_EQ(stop.exit_code, 0) << stop.output;
    ::unsetenv("SLURM_ONE_NODE_KEEP");
    ::unsetenv("SLURM_CONF");
  }

  static std::string cluster_script() { return quoted(source_dir() / "tools/scripts/one_node_cluster.sh"); }
  std::string cluster(const std::string& command) const {
    return cluster_script() + " -d " + quoted(cluster_dir) + " " + command;
  }

  // Runs ochre-slurm; returns the job ids it prints ("jobs: array=12 merge=13 report=14").
  std::map<std::string, std::string> ochre_slurm(const std::string& args) {
    const CommandResult r =
        shell("cd " + quoted(work) + " && " + quoted(bin_dir() / "ochre-slurm") + " " + args);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::map<std::string, std::string> ids;
    static const std::regex id(R"((array|merge|report)=(\d+))");
    const size_t line = r.output.find("jobs: ");
    if (line == std::string::npos) {
      ADD_FAILURE() << "no job ids in: " << r.output;
      return ids;
    }
    const std::string text = r.output.substr(line, r.output.find('\n', line) - line);
    for (std::sregex_iterator it(text.begin(), text.end(), id), end; it != end; ++it)
      ids[(*it)[1]] = (*it)[2];
    return ids;
  }

  // Waits until the job (or every task of an array) has ended; returns the states ("1_2 COMPLETED None").
  std::string wait(const std::string& job) { return shell(cluster("wait " + job)).output; }

  std::string state(const std::string& job) {
    std::string text = shell("squeue -h -t all -j " + job + " -o %T").output;
    return text.substr(0, text.find('\n'));
  }

  // A job of 4 tasks: `split` is "--parts 4" or, e.g., "--tiles 2x1 --parts 2".
  std::string new_job_args(const std::string& split, const std::string& name) const {
    return quoted(source_dir() / kScene) + " " + split + " " + kSettings + " --dir " + name + " --png " +
           name + "/final.png --ochre " + quoted(bin_dir() / "ochre");
  }

  static constexpr const char* kScene = "scenes/cornell-box/cornell-box.json";
  static constexpr const char* kSettings = "--spp 16 --resolution 64x48 --aovs";
  fs::path work = scratch_dir();
  fs::path cluster_dir;
};

TEST_F(Slurm, FourTaskArrayAndMergeGiveTheSingleProcessImage) {
  auto ids = ochre_slurm(new_job_args("--parts 4", "job"));
  ASSERT_EQ(ids.size(), 3u);
  const std::string merge_states = wait(ids["merge"]);
  EXPECT_TRUE(merge_states.find(ids["merge"] + " COMPLETED") != std::string::npos) << merge_states;
  EXPECT_EQ(state(ids["report"]), "CANCELLED") << "the report job runs only when a task fails";
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(fs::exists(work / fmt::format("job/parts/part-{}.exr", i)));
  EXPECT_TRUE(same_exr_pixels(work / "single.exr", work / "job/cornell-box.exr"));
  EXPECT_TRUE(fs::exists(work / "job/final.png"));
}

TEST_F(Slurm, ACancelledTaskIsReportedByTheMergeAndResubmittedAlone) {
  // Two tiles times two sample ranges; held at submission, so that task 2 (tile 1, samples 0:8) is
  // cancelled before it runs.
  auto ids = ochre_slurm(new_job_args("--tiles 2x1 --parts 2", "job") + " -- --hold");
  ASSERT_EQ(ids.size(), 3u);
  ASSERT_EQ(shell("scancel " + ids["array"] + "_2").exit_code, 0);
  ASSERT_EQ(shell("scontrol release " + ids["array"] + "," + ids["merge"] + "," + ids["report"]).exit_code,
            0);
  wait(ids["report"]);
  EXPECT_EQ(state(ids["report"]), "FAILED") << "the merge of the parts present fails, naming what is missing";
  EXPECT_EQ(state(ids["merge"]), "CANCELLED");
  std::string report;
  for (const auto& entry : fs::directory_iterator(work / "job/logs"))
    if (entry.path().filename().string().rfind("report-", 0) == 0) report = read_file_contents(entry.path());
  EXPECT_TRUE(report.find("missing: samples 0:8 of region 32,0,64,48") != std::string::npos) << report;
  EXPECT_TRUE(report.find("parts without a file: 2 (of 4)") != std::string::npos) << report;
  EXPECT_TRUE(report.find("ochre-slurm --resubmit") != std::string::npos) << report;
  EXPECT_FALSE(fs::exists(work / "job/cornell-box.exr"));

  const auto rendered = fs::last_write_time(work / "job/parts/part-0.exr");
  auto again = ochre_slurm("--resubmit job --");  // without the --hold of the first submission
  ASSERT_EQ(again.size(), 3u);
  const std::string merge_states = wait(again["merge"]);
  EXPECT_TRUE(merge_states.find(again["merge"] + " COMPLETED") != std::string::npos) << merge_states;
  const std::string tasks = shell("squeue -h -t all -j " + again["array"] + " -o %i").output;
  EXPECT_EQ(tasks, again["array"] + "_2\n") << "only the missing part is rendered again";
  EXPECT_EQ(fs::last_write_time(work / "job/parts/part-0.exr"), rendered);
  EXPECT_TRUE(same_exr_pixels(work / "single.exr", work / "job/cornell-box.exr"));
}

// Frames and parts of frames as one array (task K: frame 1 + K / 2, part K % 2), each frame merged to the
// bits of the same frame of `ochre render --frames 2`; --status reads the queue (held: every part pending)
// and the parts; the tasks render on the CPUs Slurm allots (--cpus-per-task).
TEST_F(Slurm, FramesAndPartsOfFramesAsOneArrayMergeToTheSequence) {
  write_text(work / "torch.json", kTorchScene);
  ASSERT_EQ(run_ochre("render torch.json --frames 2 -o seq.exr -q", work).exit_code, 0);
  auto ids =
      ochre_slurm(quoted(work / "torch.json") + " --frames 2 --parts 2 --dir frames --png frames/torch.png " +
                  "--ochre " + quoted(bin_dir() / "ochre") + " -- --hold --cpus-per-task=1");
  ASSERT_EQ(ids.size(), 3u);
  const std::string slurm = "cd " + quoted(work) + " && " + quoted(bin_dir() / "ochre-slurm");
  const CommandResult held = shell(slurm + " --status frames");
  EXPECT_EQ(held.exit_code, 0) << held.output;
  EXPECT_NE(held.output.find("parts rendered: 0 of 4 (pending 4)"), std::string::npos) << held.output;
  EXPECT_NE(
      held.output.find("jobs: merge " + ids["merge"] + " PENDING, report " + ids["report"] + " PENDING"),
      std::string::npos)
      << held.output;

  ASSERT_EQ(shell("scontrol release " + ids["array"] + "," + ids["merge"] + "," + ids["report"]).exit_code,
            0);
  const std::string merge_states = wait(ids["merge"]);
  EXPECT_TRUE(merge_states.find(ids["merge"] + " COMPLETED") != std::string::npos) << merge_states;
  for (const char* part : {"part-0.0001.exr", "part-1.0001.exr", "part-0.0002.exr", "part-1.0002.exr"})
    EXPECT_TRUE(fs::exists(work / "frames/parts" / part)) << part;
  EXPECT_TRUE(same_exr_pixels(work / "seq.0001.exr", work / "frames/torch.0001.exr"));
  EXPECT_TRUE(same_exr_pixels(work / "seq.0002.exr", work / "frames/torch.0002.exr"));
  EXPECT_TRUE(fs::exists(work / "frames/torch.0002.png"));
  const std::string log = read_file_contents(work / fmt::format("frames/logs/render-{}_3.log", ids["array"]));
  EXPECT_NE(log.find("on 1 threads"), std::string::npos) << log;

  const CommandResult done = shell(slurm + " --status frames");
  EXPECT_EQ(done.exit_code, 0) << done.output;
  EXPECT_NE(done.output.find("parts rendered: 4 of 4\n"), std::string::npos) << done.output;
  EXPECT_NE(done.output.find("frames merged: 2 of 2"), std::string::npos) << done.output;
  EXPECT_NE(done.output.find("jobs: merge " + ids["merge"] + " COMPLETED"), std::string::npos) << done.output;
}

}  // namespace
}  // namespace ochre::test::slurm_test
