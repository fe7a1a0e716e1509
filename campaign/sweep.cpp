#include "campaign/sweep.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <deque>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "campaign/point_record.hpp"
#include "campaign/table.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/case.hpp"

namespace suspend::campaign {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {
// The exit of a point's child whose exec failed (the shell's "command not found").
constexpr int could_not_start = 127;
std::atomic<int> stop_signal{0};
extern "C" void on_sweep_signal(int sig) { stop_signal.store(sig); }

std::string now_text() {
  const std::time_t t = std::time(nullptr);
  char b[16];
  std::strftime(b, sizeof b, "%H:%M:%S", std::localtime(&t));
  return b;
}

// The last line of a point's log that starts with "error:" or "jammed:", for the table.
std::string last_reason(const fs::path& log) {
  std::ifstream in(log);
  std::string line, reason;
  while (std::getline(in, line))
    if (line.rfind("error:", 0) == 0 || line.rfind("jammed:", 0) == 0) reason = line;
  return reason;
}

// ", eta_r = M +- E" from a finished point's summary, for the progress line.
std::string eta_text(const fs::path& point_dir) {
  std::ifstream in(point_dir / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in, nullptr, false);
  if (s.is_discarded() || !s.contains("eta_r") || !s["eta_r"]["mean"].is_number()) return "";
  char b[96];
  std::snprintf(b, sizeof b, ", eta_r = %.4g +- %.2g", s["eta_r"]["mean"].get<double>(),
                s["eta_r"]["sem"].is_number() ? s["eta_r"]["sem"].get<double>() : 0.0);
  return b;
}

// When the point's checkpoint was last written (the earliest time there is when it has none).
fs::file_time_type checkpoint_time(const fs::path& point_dir) {
  std::error_code ec;
  const fs::file_time_type t = fs::last_write_time(point_dir / "checkpoint.h5", ec);
  return ec ? fs::file_time_type::min() : t;
}

// A run that ended (summary.json says done or jammed) while its record still says otherwise: the sweep was killed
// between the run's end and the record. Records it as it ended instead of running it again.
bool recover_ended_run(const fs::path& point_dir, PointRecord& r) {
  std::ifstream in(point_dir / "summary.json");
  if (!in) return false;
  const nlohmann::json s = nlohmann::json::parse(in, nullptr, false);
  if (s.is_discarded() || !s.is_object() || !s.contains("status") || !s["status"].is_string()) return false;
  const std::string status = s["status"];
  if (status != "done" && status != "jammed") return false;
  r.status = status;
  r.exit_code = status == "done" ? 0 : exit_jammed;
  r.message = status == "jammed" ? last_reason(point_dir / "log.txt") : std::string();
  write_record(point_dir, r);
  return true;
}

// The CPU time (user + system) a running child has used so far, from /proc/PID/stat (fields 14 and 15, in clock
// ticks); 0 where that cannot be read.
double cpu_seconds_so_far(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t name_end = text.rfind(')');  // the command name may hold spaces; the fields follow it
  if (name_end == std::string::npos) return 0.0;
  std::istringstream fields(text.substr(name_end + 1));
  std::string field;
  double ticks = 0.0;
  for (int k = 3; k <= 15 && fields >> field; ++k)
    if (k >= 14) ticks += std::strtod(field.c_str(), nullptr);
  const long per_second = sysconf(_SC_CLK_TCK);
  return per_second > 0 ? ticks / static_cast<double>(per_second) : 0.0;
}

double cpu_seconds_of(const rusage& u) {
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Job {
  pid_t pid = -1;
  const Point* point = nullptr;
  Clock::time_point start;
  io::FolderLock lock;
  PointRecord record;
  bool over_budget = false;
  fs::file_time_type checkpointed = fs::file_time_type::min();  // last checkpoint its record's wall time covers
};
}  // namespace

namespace {
// The points DIR/sweep.json records (an empty object for a new folder), each checked against the campaign.
nlohmann::ordered_json checked_points(const Campaign& c, const fs::path& dir) {
  const fs::path record = dir / "sweep.json";
  nlohmann::ordered_json known = nlohmann::ordered_json::object();
  if (!fs::exists(record)) return known;
  std::ifstream in(record);
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.contains("points"))
    throw InputError(record.string() + ": unreadable; it records the campaign this folder was started with");
  known = j["points"];
  for (const auto& [name, identity] : known.items()) {
    const Point* p = c.find(name);
    if (!p)
      throw InputError("campaign changed: point " + name + " of " + dir.string() +
                       " is no longer in the campaign (only adding points is allowed; use another --out)");
    const std::string changes = io::case_changes(identity.get<std::string>(), p->identity, io::result_identity);
    if (!changes.empty())
      throw InputError("campaign changed: point " + name + " now differs in " + changes +
                       " (only adding points is allowed; use another --out)");
  }
  return known;
}
}  // namespace

void check_points(const Campaign& c, const fs::path& dir) { checked_points(c, dir); }

void check_and_record_points(const Campaign& c, const fs::path& dir) {
  nlohmann::ordered_json known = checked_points(c, dir);
  for (const Point& p : c.points) known[p.name] = p.identity;
  fs::create_directories(dir);
  io::write_text_atomically((dir / "sweep.json").string(),
                            nlohmann::ordered_json{{"campaign", c.source}, {"points", known}}.dump(1) + "\n");
}

std::string own_executable() {
  std::string exe = fs::read_symlink("/proc/self/exe").string();
  const std::string deleted = " (deleted)";
  if (exe.size() > deleted.size() && exe.compare(exe.size() - deleted.size(), deleted.size(), deleted) == 0)
    exe.resize(exe.size() - deleted.size());
  return exe;
}

int run_sweep(const Campaign& c, const SweepOptions& o) {
  std::vector<const Point*> selected;
  if (!o.only_point.empty()) {
    const Point* p = c.find(o.only_point);
    if (!p) throw InputError("--point: '" + o.only_point + "' is not a point of this campaign (see --list)");
    selected.push_back(p);
  } else {
    for (const Point& p : c.points) selected.push_back(&p);
  }
  const std::string exe = o.executable.empty() ? own_executable() : o.executable;
  check_and_record_points(c, o.out_dir);

  std::deque<const Point*> todo;
  int skipped_done = 0, skipped_failed = 0;
  for (const Point* p : selected) {
    const PointRecord r = read_record(point_dir(o.out_dir, *p));
    if (r.status == "done" || r.status == "jammed") ++skipped_done;
    else if (r.status == "failed" && !o.retry_failed) ++skipped_failed;
    else todo.push_back(p);
  }
  write_table(c, o.out_dir);
  auto say = [&](const std::string& s) {
    if (!o.quiet) std::printf("[%s] %s\n", now_text().c_str(), s.c_str()), std::fflush(stdout);
  };
  say(std::to_string(selected.size()) + " point(s): " + std::to_string(skipped_done) + " finished, " +
      std::to_string(skipped_failed) + " failed (kept; --retry-failed runs them again), " +
      std::to_string(todo.size()) + " to run, " + std::to_string(o.jobs) + " at a time on " +
      std::to_string(o.threads) + " thread(s) each");

  stop_signal.store(0);
  struct sigaction sa {};
  sa.sa_handler = on_sweep_signal;
  sigemptyset(&sa.sa_mask);
  struct sigaction old_int {}, old_term {};
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  const pid_t parent = getpid();

  std::vector<Job> jobs;
  int failed = 0, busy_elsewhere = 0;
  auto start = [&](const Point* p) {
    const fs::path pd = point_dir(o.out_dir, *p);
    fs::create_directories(pd);
    io::FolderLock lock = lock_point(pd);
    if (!lock.held()) {
      ++busy_elsewhere;
      say(p->name + " is being run by " + lock.holder() + "; skipped");
      return;
    }
    // Read again under the lock: another sweep on this folder may have finished the point since the list was made.
    PointRecord r = read_record(pd);
    if (r.status == "done" || r.status == "jammed" || (r.status == "failed" && !o.retry_failed)) {
      say(p->name + " was ended by another process (" + r.status + "); skipped");
      return;
    }
    if (recover_ended_run(pd, r)) {
      say(r.status + " " + p->name + " (its run had ended before its record; recorded now)" + eta_text(pd));
      write_table(c, o.out_dir);
      return;
    }
    std::vector<std::string> args = {exe, "run", c.case_file};
    for (const std::string& s : c.overrides(*p)) args.insert(args.end(), {"--set", s});
    args.insert(args.end(), {"--threads", std::to_string(o.threads)});
    if (fs::is_regular_file(pd / "checkpoint.h5")) {
      args.insert(args.end(), {"--restart", (pd / "checkpoint.h5").string()});
    } else {  // never checkpointed: start again from nothing
      for (const char* f : {"run.h5", "run.xdmf", "summary.json"}) fs::remove(pd / f);
      args.insert(args.end(), {"--out", pd.string()});
    }
    r.status = "running";
    r.message.clear();
    ++r.runs;
    r.initial.clear();
    for (const Assignment& a : p->parameters)
      if (a.key == "particles.initial") r.initial = a.value;
    write_record(pd, r);
    const std::string log = (pd / "log.txt").string();
    const pid_t pid = fork();
    if (pid == 0) {
      // A point outlives no sweep: when the sweep dies, the run checkpoints and stops (SIGTERM).
      prctl(PR_SET_PDEATHSIG, SIGTERM);
      if (getppid() != parent) _exit(143);
      fcntl(lock.fd(), F_SETFD, 0);  // the run holds the point's lock too, until it has checkpointed and ended
      signal(SIGINT, SIG_IGN);  // Ctrl-C reaches the whole process group; the sweep forwards it as SIGTERM
      signal(SIGTERM, SIG_DFL);
      const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
      if (fd >= 0) dup2(fd, 1), dup2(fd, 2);
      std::vector<char*> argv;
      for (std::string& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(exe.c_str(), argv.data());
      std::fprintf(stderr, "error: cannot start %s: %s\n", exe.c_str(), std::strerror(errno));
      _exit(could_not_start);
    }
    if (pid < 0) throw std::runtime_error("fork failed for point " + p->name);
    say("start " + p->name + (r.runs > 1 ? " (continued, run " + std::to_string(r.runs) + ")" : ""));
    jobs.push_back({pid, p, Clock::now(), std::move(lock), r, false, checkpoint_time(pd)});
  };

  bool disk_full = false;  // a point stopped with exit_output_error
  bool not_started = false;  // a point's run could not be started: the program is missing or not executable
  auto finish = [&](Job& j, int status, const rusage& usage) {
    const fs::path pd = point_dir(o.out_dir, *j.point);
    PointRecord& r = j.record;
    r.wall_seconds += std::chrono::duration<double>(Clock::now() - j.start).count();
    r.cpu_seconds += cpu_seconds_of(usage);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.exit_code = code;
    const std::string reason = last_reason(pd / "log.txt");
    if (code == 0) {
      r.status = "done";
    } else if (code == exit_jammed) {
      r.status = "jammed";
      r.message = reason;
    } else if ((code == 143 || code == 130) && stop_signal.load() && !j.over_budget) {
      r.status = "pending";  // stopped with the sweep: continues from its checkpoint next time
    } else if (code == could_not_start && reason.rfind("error: cannot start", 0) == 0) {
      // Not the point's failure: it never ran. It stays pending, and no more points are started.
      r.status = "pending";
      r.message = reason;
      if (!not_started) say(reason + ": no more points are started; the same command continues the sweep");
      not_started = true;
    } else if (code == exit_output_error) {
      // The disk is full for every point: none is started any more, this one continues once there is room.
      r.status = "pending";
      r.message = reason;
      if (!disk_full) say("the disk is full (" + reason + "): no more points are started; once there is room, the "
                          "same command continues the sweep");
      disk_full = true;
    } else {
      r.status = "failed";
      r.message = j.over_budget ? "wall-clock budget of " + std::to_string(o.point_seconds) +
                                      " s used up (stopped at a checkpoint; continue with --retry-failed)"
                                : reason.empty() ? "exit code " + std::to_string(code) : reason;
      ++failed;
    }
    write_record(pd, r);
    write_table(c, o.out_dir);
    say(r.status + " " + j.point->name + (r.message.empty() ? "" : ": " + r.message) + eta_text(pd));
  };

  bool forwarded = false;
  while ((!todo.empty() && !stop_signal.load() && !disk_full && !not_started) || !jobs.empty()) {
    while (static_cast<int>(jobs.size()) < o.jobs && !todo.empty() && !stop_signal.load() && !disk_full &&
           !not_started) {
      const Point* p = todo.front();
      todo.pop_front();
      start(p);
    }
    if (stop_signal.load() && !forwarded) {
      for (Job& j : jobs) kill(j.pid, SIGTERM);
      forwarded = true;
      say("stopping: each running point checkpoints; the same command continues the sweep");
    }
    // A point's record gains its wall time at each new checkpoint, so that SIGKILL of the sweep (a machine or
    // session that ends) loses the time as it loses the work: since the last checkpoint.
    for (Job& j : jobs) {
      const fs::path pd = point_dir(o.out_dir, *j.point);
      const fs::file_time_type t = checkpoint_time(pd);
      if (t <= j.checkpointed) continue;
      j.checkpointed = t;
      PointRecord so_far = j.record;
      so_far.wall_seconds += std::chrono::duration<double>(Clock::now() - j.start).count();
      so_far.cpu_seconds += cpu_seconds_so_far(j.pid);
      write_record(pd, so_far);
    }
    for (Job& j : jobs)
      if (o.point_seconds > 0 && !j.over_budget &&
          std::chrono::duration<double>(Clock::now() - j.start).count() > o.point_seconds) {
        kill(j.pid, SIGTERM);
        j.over_budget = true;
      }
    int status = 0;
    rusage usage{};
    const pid_t done = wait4(-1, &status, WNOHANG, &usage);  // with the child's CPU time
    if (done > 0) {
      for (std::size_t k = 0; k < jobs.size(); ++k)
        if (jobs[k].pid == done) {
          finish(jobs[k], status, usage);
          jobs.erase(jobs.begin() + static_cast<long>(k));
          break;
        }
      continue;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  write_table(c, o.out_dir);

  std::map<std::string, int> counts;
  for (const Point* p : selected) {
    std::string s = read_record(point_dir(o.out_dir, *p)).status;
    if (s == "running" && !locked_elsewhere(point_dir(o.out_dir, *p))) s = "pending";
    ++counts[s];
  }
  std::string line;
  for (const auto& [s, n] : counts) line += (line.empty() ? "" : ", ") + std::to_string(n) + " " + s;
  say(line + "; table: " + (o.out_dir / "campaign.json").string() + ", " + (o.out_dir / "campaign.csv").string());
  if (const int sig = stop_signal.load()) return 128 + sig;
  if (disk_full || not_started) return exit_output_error;
  return failed > 0 || counts["failed"] > 0 ? exit_numerical_error : 0;
}

}  // namespace suspend::campaign
