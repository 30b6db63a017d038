// The run log (rig/results/run_log.hpp): folding it gives the byte-identical results.json of
// the whole-file writer; a kill leaves whole records only; a full disk or a file size limit
// leaves whole records and says why (the errno text).

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "rig/results/fold_run_log.hpp"
#include "rig/results/junit.hpp"
#include "rig/results/report_html.hpp"
#include "rig/results/results_json.hpp"
#include "rig/results/run_log.hpp"
#include "sample_campaign.hpp"
#include "tests/tools/scratch_files.hpp"

namespace hilrig::rig {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return hilrig::test::scratch_dir("results", name); }

std::size_t lines(const fs::path& path) {
  const std::string text = hilrig::test::read_file(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// Writes the campaign through a run log, run by run, as `hilrig run` does.
void log_campaign(const fs::path& path, const CampaignResult& campaign) {
  RunLog log(path, campaign);
  for (const RunResult& run : campaign.runs) log.append(run);
}

// Property over campaign sizes (0 runs, fault runs caught and missed, wall-clock facts): the
// fold is the same results.json, byte for byte, as writing the whole result at once.
TEST(RunLog, FoldIsByteIdenticalToTheWholeFileWriter) {
  const fs::path dir = scratch("fold");
  for (std::size_t n : {0U, 1U, 2U, 3U, 7U, 40U}) {
    CampaignResult whole = test::sample_campaign(n);
    if (n == 7) whole.runs.push_back(test::fault_run(7, "late_output", false)); // a fault missed
    whole.planned_runs = whole.runs.size() + (n == 40 ? 2 : 0);                 // and one incomplete
    whole.started_at = "2026-01-02T03:04:05Z";
    whole.host = "bench-3";
    finalize(whole);
    log_campaign(dir / kRunLogName, whole);
    EXPECT_EQ(lines(dir / kRunLogName), whole.runs.size() + 1) << n; // header + one line a run
    write_results_file(dir / "whole.json", whole);
    write_results_file(dir / "folded.json", read_run_log(dir / kRunLogName));
    EXPECT_EQ(hilrig::test::read_file(dir / "folded.json"), hilrig::test::read_file(dir / "whole.json")) << n;
    // read_results_file folds a *.jsonl too (what `hilrig merge OUT.json DIR/runs.jsonl` reads).
    EXPECT_EQ(to_json_text(read_results_file(dir / kRunLogName)), hilrig::test::read_file(dir / "whole.json"))
        << n;
  }
}

// The fold `hilrig run` ends with (fold_run_log: the log read a record at a time for each
// file) writes the same results.json, junit.xml and report.html, byte for byte, as the
// in-memory writers given every run at once: for no run, a few, an interrupted result, and a
// campaign long enough (400 runs) that the report shows most runs as table rows.
TEST(RunLog, FoldedOutputsAreTheInMemoryWritersBytes) {
  const fs::path dir = scratch("fold_outputs");
  for (std::size_t n : {0U, 1U, 3U, 7U, 400U}) {
    CampaignResult whole = test::sample_campaign(n);
    if (n == 7) whole.runs.push_back(test::fault_run(7, "late_output", false)); // a fault missed
    whole.planned_runs = whole.runs.size() + (n == 3 ? 1 : 0);
    if (n == 3) whole.interrupted = "SIGTERM";
    whole.started_at = "2026-01-02T03:04:05Z";
    whole.host = "bench-3";
    finalize(whole);
    JunitClock clock{"2026-01-02T03:04:05Z", "bench-3", {}};
    for (const RunResult& run : whole.runs)
      clock.run_seconds[run.index] = 0.25 * static_cast<double>(run.index);
    log_campaign(dir / kRunLogName, whole);
    const CampaignResult folded = fold_run_log(dir / kRunLogName, dir, whole, clock);
    EXPECT_TRUE(folded.runs.empty()) << n; // the fold hands back no run
    EXPECT_EQ(folded.totals, whole.totals) << n;
    EXPECT_EQ(folded.verdict, whole.verdict) << n;
    EXPECT_EQ(folded.complete, whole.complete) << n;
    EXPECT_EQ(hilrig::test::read_file(dir / "results.json"), to_json_text(whole)) << n;
    EXPECT_EQ(hilrig::test::read_file(dir / "junit.xml"), to_junit_xml(whole, clock)) << n;
    EXPECT_EQ(hilrig::test::read_file(dir / "report.html"), to_report_html(whole)) << n;
    for (const auto& e : fs::directory_iterator(dir)) EXPECT_NE(e.path().extension(), ".tmp") << n;
  }
}

// A run with every kind of field the log's writer holds and its reader parses back: window
// traces (a logic lane, a count lane, an analog lane), probes, a motion record, a value that
// is not a number (every fourth run) and doubles no short decimal writes (1/3, 0.1 + 0.2, -0).
RunResult rich_run(std::uint64_t index) {
  RunResult r = test::nominal_run(index, 10.0 + 1.0 / 3.0);
  CheckResult& c = r.checks[1];
  WindowTrace w{*c.measurements[0].window, TraceWindow{Nanos{150'000'000}, Nanos{160'000'000}}, {}};
  w.lanes.push_back(
      TraceLane{"enc.A", LaneRole::Stimulus, {{Nanos{150'000'000}, 0}, {Nanos{151'000'001}, 1}}, 0});
  w.lanes.push_back(
      TraceLane{"shaft.count", LaneRole::Count, {{Nanos{150'000'000}, -3}, {Nanos{152'000'000}, 94}}, 7});
  TraceLane stator{
      "resolver.sin",
      LaneRole::Stimulus,
      {{Nanos{150'000'000}, 0, -0.0}, {Nanos{150'100'000}, 0, 0.1 + 0.2}, {Nanos{150'200'000}, 0, -1e-300}},
      0};
  stator.real = true;
  w.lanes.push_back(stator);
  c.traces.push_back(w);
  c.probes.push_back(Probe{Nanos{2'500'000}, true, Nanos{100'000}});
  c.probes.push_back(Probe{Nanos{1'250'000}, false, std::nullopt});
  if (index % 4 == 1) {
    Measurement broken = c.measurements[0];
    broken.name = "ls1-advance.edge1";
    broken.value = std::numeric_limits<double>::quiet_NaN();
    broken.outcome = Outcome::Error;
    c.measurements.push_back(broken);
  }
  r.motion.points = {{Nanos{0}, 0.0, 0.0}, {Nanos{1'000'000}, 1.0 / 3.0, 333.3333333333333}};
  r.motion.events = {{Nanos{500'000}, "valve off: brake applied"}};
  r.observations.push_back(Observation{"dut.word", 2.0 / 3.0, "", Nanos{-1}});
  return r;
}

// The fold `hilrig run` makes from the log's writer (fold_run_log(RunLog&): the runs it held
// in memory, or, past its budget, the file read back) writes the same results.json,
// junit.xml and report.html, byte for byte, as the fold of the file alone: budgets that hold
// every run, none (dropped at the first) and some (dropped part way), over campaigns of no
// run, a few, rich runs, an interrupted one and 60 runs.
TEST(RunLog, WritersFoldIsTheFilesFold) {
  const fs::path dir = scratch("writer_fold");
  for (std::size_t n : {0U, 1U, 3U, 7U, 60U}) {
    CampaignResult whole = test::sample_campaign(n);
    if (n == 7) {
      whole.runs.push_back(test::fault_run(7, "late_output", false));
      for (std::uint64_t i = 8; i < 14; ++i) whole.runs.push_back(rich_run(i));
    }
    whole.planned_runs = whole.runs.size() + (n == 3 ? 1 : 0);
    finalize(whole);
    CampaignResult facts;
    if (n == 3) facts.interrupted = "SIGTERM";
    facts.started_at = "2026-01-02T03:04:05Z";
    facts.host = "bench-3";
    JunitClock clock{"2026-01-02T03:04:05Z", "bench-3", {}};
    for (const RunResult& run : whole.runs)
      clock.run_seconds[run.index] = 0.25 * static_cast<double>(run.index);
    for (const std::size_t budget : {kRunLogHeldBytes, std::size_t{0}, std::size_t{20'000}}) {
      const std::string what = fmt::format("{} runs, budget {}", n, budget);
      const fs::path held = dir / "held";
      const fs::path read = dir / "read";
      fs::create_directories(held);
      fs::create_directories(read);
      RunLog log(held / kRunLogName, whole, budget);
      for (const RunResult& run : whole.runs) log.append(run);
      if (budget == kRunLogHeldBytes || whole.runs.empty()) {
        EXPECT_TRUE(log.holds_runs()) << what;
      } else if (budget == 0 || n == 60) {
        EXPECT_FALSE(log.holds_runs()) << what; // read back from the file
      }

      // Each record is {"run": the judged run's object} dumped compact, whether the writer
      // made it from the indented dump it holds or dumped it itself (past its budget).
      std::istringstream lines(hilrig::test::read_file(held / kRunLogName));
      std::string line;
      std::getline(lines, line); // the header
      for (const RunResult& run : whole.runs) {
        RunResult judged = run;
        judge(judged);
        ASSERT_TRUE(std::getline(lines, line)) << what;
        EXPECT_EQ(line, nlohmann::json({{"run", run_to_json(judged)}}).dump())
            << what << ", run " << run.index;
      }
      EXPECT_FALSE(std::getline(lines, line)) << what;

      const CampaignResult from_writer = fold_run_log(log, held, facts, clock);
      const CampaignResult from_file = fold_run_log(held / kRunLogName, read, facts, clock);
      EXPECT_EQ(from_writer.totals, from_file.totals) << what;
      EXPECT_EQ(from_writer.verdict, from_file.verdict) << what;
      EXPECT_EQ(from_writer.complete, from_file.complete) << what;
      EXPECT_EQ(to_json_text(from_writer), to_json_text(from_file)) << what; // the summaries
      for (const char* file : {"results.json", "junit.xml", "report.html"})
        EXPECT_EQ(hilrig::test::read_file(held / file), hilrig::test::read_file(read / file))
            << what << ": " << file;
    }
  }
}

// The writer's summary of runs appended out of run order is the reader's refusal.
TEST(RunLog, WritersSummaryRefusesRunsOutOfOrder) {
  const fs::path dir = scratch("writer_order");
  CampaignResult whole = test::sample_campaign(3);
  RunLog log(dir / kRunLogName, whole);
  log.append(whole.runs[0]);
  log.append(whole.runs[2]);
  log.append(whole.runs[1]);
  try {
    (void)log.summary();
    ADD_FAILURE() << "runs out of run order were summed up";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(kRunLogName + std::string(":4: run 1 after run 2")),
              std::string::npos)
        << e.what();
  }
}

// A log whose runs are not in run order is refused with its file and line (the fold writes
// each file in one pass, in the order of the records).
TEST(RunLog, FoldRefusesRunsOutOfOrder) {
  const fs::path dir = scratch("fold_order");
  CampaignResult whole = test::sample_campaign(3);
  {
    RunLog log(dir / kRunLogName, whole);
    log.append(whole.runs[0]);
    log.append(whole.runs[2]);
    log.append(whole.runs[1]);
  }
  try {
    (void)read_run_log_summary(dir / kRunLogName);
    ADD_FAILURE() << "a log out of run order was folded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(kRunLogName + std::string(":4: run 1 after run 2")),
              std::string::npos)
        << e.what();
  }
}

// to_json_text splices each run's own dump into the document: the same bytes as dumping the
// whole document at once, for no run, one, many, and names that JSON must escape.
TEST(RunLog, StreamedResultsTextIsTheWholeDocumentDump) {
  for (std::size_t n : {0U, 1U, 2U, 5U, 30U}) {
    CampaignResult r = test::sample_campaign(n);
    if (n == 2) {
      r.runs[0].name = "line\nbreak \"quoted\" \\ tab\t \u00b5s";
      r.runs[1].error = "{\n  \"runs\": []\n}";
    }
    EXPECT_EQ(to_json_text(r), to_json(r).dump(2) + "\n") << n;
  }
}

// A process killed (SIGKILL: no handler, no flush) after N appended runs leaves a log of N whole
// records, which folds into an incomplete result with exactly those runs.
TEST(RunLog, KillAfterNRunsLeavesNWholeRecords) {
  const fs::path dir = scratch("kill");
  const CampaignResult whole = test::sample_campaign(6);
  for (std::size_t n = 0; n <= whole.runs.size(); ++n) {
    const fs::path path = dir / fmt::format("kill{}.jsonl", n);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      RunLog log(path, whole);
      for (std::size_t i = 0; i < n; ++i) log.append(whole.runs[i]);
      ::raise(SIGKILL);
      ::_exit(1);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    EXPECT_EQ(lines(path), n + 1);
    const CampaignResult folded = read_run_log(path);
    ASSERT_EQ(folded.runs.size(), n);
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(folded.runs[i].index, whole.runs[i].index);
    EXPECT_EQ(folded.planned_runs, 6U);
    EXPECT_EQ(folded.complete, n == 6);
    EXPECT_EQ(folded.totals.runs, n);
  }
}

// A record cut short (a power loss mid-write: no newline at the end) is not a run.
TEST(RunLog, TornLastRecordIsIgnored) {
  const fs::path dir = scratch("torn");
  const CampaignResult whole = test::sample_campaign(3);
  log_campaign(dir / kRunLogName, whole);
  const std::string text = hilrig::test::read_file(dir / kRunLogName);
  const std::size_t last = text.rfind('\n', text.size() - 2) + 1; // start of the last record
  for (std::size_t cut : {last + 1, last + 10, text.size() - 1}) {
    std::ofstream(dir / "cut.jsonl", std::ios::binary) << text.substr(0, cut);
    EXPECT_EQ(read_run_log(dir / "cut.jsonl").runs.size(), 2U) << cut;
  }
  // A broken record with its newline is damage, named by file and line.
  std::ofstream(dir / "bad.jsonl", std::ios::binary) << text.substr(0, last) << "{\"run\": 5}\n";
  try {
    (void)read_run_log(dir / "bad.jsonl");
    ADD_FAILURE() << "a broken record was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.jsonl:4:"), std::string::npos) << e.what();
  }
  std::ofstream(dir / "results.jsonl", std::ios::binary) << to_json(whole).dump() << "\n";
  EXPECT_THROW((void)read_run_log(dir / "results.jsonl"), std::runtime_error); // not a run log
}

// Runs `body` in a child whose files may not grow beyond `limit` bytes (RLIMIT_FSIZE, with
// SIGXFSZ ignored so write() fails with EFBIG); returns the child's exit status.
template <class Body> int with_file_size_limit(rlim_t limit, Body body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit r{limit, limit};
    if (::setrlimit(RLIMIT_FSIZE, &r) != 0) ::_exit(90);
    ::_exit(body());
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 99;
}

bool says(const std::exception& e, int err) {
  return std::string(e.what()).find(std::strerror(err)) != std::string::npos;
}

// EFBIG mid-campaign: the record that does not fit is cut off again, the log keeps its whole
// records, and the message carries the errno text.
TEST(RunLog, FileSizeLimitKeepsWholeRecordsAndSaysWhy) {
  const fs::path dir = scratch("efbig");
  const CampaignResult whole = test::sample_campaign(5);
  log_campaign(dir / "full.jsonl", whole);
  const std::string text = hilrig::test::read_file(dir / "full.jsonl");
  // Room for the header and two records, and part of the third.
  std::size_t end = 0;
  for (int i = 0; i < 3; ++i) end = text.find('\n', end) + 1;
  const fs::path path = dir / kRunLogName;
  const int status = with_file_size_limit(end + 20, [&] {
    try {
      log_campaign(path, whole);
      return 1;
    } catch (const std::runtime_error& e) {
      return says(e, EFBIG) ? 0 : 2;
    }
  });
  EXPECT_EQ(status, 0);
  EXPECT_EQ(hilrig::test::read_file(path), text.substr(0, end)); // exactly the whole records
  EXPECT_EQ(read_run_log(path).runs.size(), 2U);
}

// ENOSPC, portably: the log is /dev/full.
TEST(RunLog, FullDiskSaysWhy) {
  const fs::path dir = scratch("enospc");
  fs::create_symlink("/dev/full", dir / kRunLogName);
  try {
    log_campaign(dir / kRunLogName, test::sample_campaign(1));
    ADD_FAILURE() << "a write to a full disk passed";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(says(e, ENOSPC)) << e.what();
  }
}

// The whole-file writer on a full disk (its temporary is /dev/full) or over a file size limit:
// the message says why and no *.tmp is left behind; the previous file stays.
TEST(WriteFileAtomically, FullDiskOrSizeLimitLeavesNoTmp) {
  const fs::path dir = scratch("atomic");
  const fs::path path = dir / "results.json";
  write_file_atomically(path, "previous\n");
  fs::create_symlink("/dev/full", dir / "results.json.tmp");
  try {
    write_file_atomically(path, std::string(100, 'x'));
    ADD_FAILURE() << "a write to a full disk passed";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(says(e, ENOSPC)) << e.what();
  }
  EXPECT_FALSE(fs::exists(fs::symlink_status(dir / "results.json.tmp")));
  EXPECT_EQ(hilrig::test::read_file(path), "previous\n");

  const int status = with_file_size_limit(50, [&] {
    try {
      write_file_atomically(path, std::string(100, 'x'));
      return 1;
    } catch (const std::runtime_error& e) {
      return says(e, EFBIG) ? 0 : 2;
    }
  });
  EXPECT_EQ(status, 0);
  EXPECT_FALSE(fs::exists(dir / "results.json.tmp"));
  EXPECT_EQ(hilrig::test::read_file(path), "previous\n");
}

// A path that is a directory (merge's or trend's --out given an existing directory): the message
// names the path and why, and no *.tmp is left beside it; the directory stays.
TEST(WriteFileAtomically, APathThatIsADirectoryLeavesNoTmp) {
  const fs::path dir = scratch("atomic_dir");
  fs::create_directories(dir / "m.json");
  try {
    write_file_atomically(dir / "m.json", "{}\n");
    ADD_FAILURE() << "a write over a directory passed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write " + (dir / "m.json").string() + ": "),
              std::string::npos)
        << e.what();
    EXPECT_TRUE(says(e, EISDIR)) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "m.json.tmp"));
  EXPECT_TRUE(fs::is_directory(dir / "m.json"));
}

// A directory given where a results.json or runs.jsonl is read (merge, compare, trend): the
// message names it, not a stream library's "basic_filebuf::underflow".
TEST(ReadResultsFile, ADirectoryIsNamed) {
  const fs::path dir = scratch("results_dir");
  for (const char* name : {"d.json", "d.jsonl"}) {
    fs::create_directories(dir / name);
    try {
      (void)read_results_file(dir / name);
      ADD_FAILURE() << "a directory was read as results";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()),
                (dir / name).string() + ": a directory, not a results.json or runs.jsonl");
    }
  }
}

// A whole number the writer wrote (a run index, a seed) read back as one: a negative index, a
// fraction or a seed past 2^64 is refused with the field and its range, not converted (-1 read
// as 18446744073709551615, 1e20 as 0).
TEST(ReadResultsFile, WholeNumbersOutOfTheirTypeAreRefused) {
  const fs::path dir = scratch("results_whole");
  const std::string text = to_json_text(test::sample_campaign(2));
  for (const auto& [field, value, says] :
       {std::tuple{"index", "-1", "run.index: -1 is not a whole number 0 .. 18446744073709551615"},
        std::tuple{"index", "1.5", "run.index: 1.5 is not a whole number"},
        std::tuple{"seed", "1e20", "run.seed: 1e+20 is not a whole number 0 .. 18446744073709551615"}}) {
    nlohmann::json j = nlohmann::json::parse(text);
    j["runs"][0][field] = nlohmann::json::parse(value);
    const fs::path path = dir / "results.json";
    std::ofstream(path) << j.dump();
    try {
      (void)read_results_file(path);
      ADD_FAILURE() << field << " = " << value << " was read";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

// Streamed: a file larger than the 1 MiB buffer, written in pieces of every size, arrives
// whole; a second name linked to it reads the same bytes.
TEST(WriteFileAtomically, StreamedWritesEveryByteAndLinksTheSameBytes) {
  const fs::path dir = scratch("atomic_stream");
  std::string expected;
  for (std::size_t i = 0; expected.size() < (std::size_t{3} << 20U); ++i)
    expected += std::string(i % 700, static_cast<char>('a' + i % 26)) + '\n';
  expected += std::string(std::size_t{2} << 20U, 'z'); // one block larger than the buffer
  write_file_atomically(dir / "big.vcd", [&](std::ostream& out) {
    std::size_t at = 0;
    for (std::size_t piece = 1; at < expected.size(); piece = piece * 3 % 100'003 + 1) {
      const std::size_t n = std::min(piece, expected.size() - at);
      if (n == 1) {
        out.put(expected[at]);
      } else {
        out.write(expected.data() + at, static_cast<std::streamsize>(n));
      }
      at += n;
    }
  });
  EXPECT_EQ(hilrig::test::read_file(dir / "big.vcd"), expected);
  EXPECT_FALSE(fs::exists(dir / "big.vcd.tmp"));
  link_file_atomically(dir / "big.vcd", dir / "copy.vcd");
  EXPECT_EQ(hilrig::test::read_file(dir / "copy.vcd"), expected);
  EXPECT_FALSE(fs::exists(dir / "copy.vcd.tmp"));
}

// Streamed onto a full disk, or a writer that throws: the error says why (or is the writer's),
// no *.tmp is left and the previous file stays.
TEST(WriteFileAtomically, StreamedFullDiskOrThrowingWriterLeavesThePreviousFile) {
  const fs::path dir = scratch("atomic_stream_fail");
  const fs::path path = dir / "trace.vcd";
  write_file_atomically(path, "previous\n");
  fs::create_symlink("/dev/full", dir / "trace.vcd.tmp");
  try {
    write_file_atomically(path, [](std::ostream& out) {
      for (int i = 0; i < 100'000; ++i) out << "b1010 !\n";
    });
    ADD_FAILURE() << "a write to a full disk passed";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(says(e, ENOSPC)) << e.what();
  }
  EXPECT_FALSE(fs::exists(fs::symlink_status(dir / "trace.vcd.tmp")));
  EXPECT_EQ(hilrig::test::read_file(path), "previous\n");
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out) {
                                       out << "half";
                                       throw std::invalid_argument("VCD: negative sample time");
                                     }),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir / "trace.vcd.tmp"));
  EXPECT_EQ(hilrig::test::read_file(path), "previous\n");
}

} // namespace
} // namespace hilrig::rig

namespace hilrig::rig {
namespace {

// The block writer behind runs.jsonl and can.log: over a file size limit the block that does
// not fit is cut off again, every block before it is kept, and the message names the file and
// the errno text; on a full disk (/dev/full) the message says so. The same with and without
// the fdatasync per block (the run log syncs, can.log does not).
TEST(AppendFile, SizeLimitKeepsTheBlocksBeforeAndSaysWhy) {
  for (const AppendFile::Sync sync : {AppendFile::Sync::EachBlock, AppendFile::Sync::None}) {
    SCOPED_TRACE(sync == AppendFile::Sync::None ? "Sync::None" : "Sync::EachBlock");
    const fs::path dir = scratch(sync == AppendFile::Sync::None ? "append_efbig_unsynced" : "append_efbig");
    const fs::path path = dir / "can.log";
    const std::string run1 = "(946684800.000000) can0 120#0000000000000000\n";
    const std::string run2 = "(946684800.001000) can0 120#0100000000000001\n";
    const int status = with_file_size_limit(run1.size() + run2.size() - 1, [&] {
      try {
        AppendFile f(path, sync);
        f.append(run1);
        f.append(run2);
        return 1;
      } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        return says(e, EFBIG) && what.find("can.log") != std::string::npos ? 0 : 2;
      }
    });
    EXPECT_EQ(status, 0);
    EXPECT_EQ(hilrig::test::read_file(path), run1);
    // Exactly room for both: both kept.
    EXPECT_EQ(with_file_size_limit(run1.size() + run2.size(),
                                   [&] {
                                     AppendFile f(path, sync);
                                     f.append(run1);
                                     f.append(run2);
                                     return 0;
                                   }),
              0);
    EXPECT_EQ(hilrig::test::read_file(path), run1 + run2);
  }
}

TEST(AppendFile, FullDiskSaysWhy) {
  const fs::path dir = scratch("append_enospc");
  fs::create_symlink("/dev/full", dir / "can.log");
  AppendFile f(dir / "can.log");
  try {
    f.append("(946684800.000000) can0 120#00\n");
    ADD_FAILURE() << "a write to a full disk passed";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(says(e, ENOSPC)) << e.what();
    EXPECT_NE(std::string(e.what()).find("can.log: No space left on device"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace hilrig::rig
