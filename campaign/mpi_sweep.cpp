#include "campaign/mpi_sweep.hpp"

#include <cstdlib>

#ifdef SUSPEND_HAVE_MPI
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <deque>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "campaign/point_record.hpp"
#include "campaign/search.hpp"
#include "campaign/table.hpp"
#include "core/error.hpp"
#endif

namespace suspend::campaign {

bool launched_by_mpi() {
#ifdef SUSPEND_HAVE_MPI
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
#endif
  return false;
}

#ifndef SUSPEND_HAVE_MPI
int run_sweep_mpi(const Campaign& c, const SweepOptions& o) {
  return c.search ? run_search_sweep(c, o) : run_sweep(c, o);
}
#else
namespace {
constexpr int tag_request = 1;  // worker -> rank 0: [code of the last point, or -1], then "give me work"
constexpr int tag_point = 2;    // rank 0 -> worker: a point name; empty: no more work

// Waits for a message without spinning a core (MPI's blocking calls busy-poll in most implementations).
MPI_Status wait_for(int source, int tag) {
  MPI_Status st;
  for (int flag = 0;;) {
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &st);
    if (flag) return st;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

int worker(const Campaign& c, SweepOptions o) {
  o.quiet = true;
  o.jobs = 1;
  int code = -1;
  for (;;) {
    MPI_Send(&code, 1, MPI_INT, 0, tag_request, MPI_COMM_WORLD);
    MPI_Status st = wait_for(0, tag_point);
    int length = 0;
    MPI_Get_count(&st, MPI_CHAR, &length);
    std::string name(static_cast<std::size_t>(length), '\0');
    MPI_Recv(name.data(), length, MPI_CHAR, 0, tag_point, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (name.empty()) return 0;
    o.only_point = name;
    // A search's points are decided as results come in: the dispatcher's plan, replayed from the same records.
    code = run_sweep(c.search ? with_search_points(c, plan_search(c, o.out_dir)) : c, o);
  }
}

int dispatcher(const Campaign& base, const SweepOptions& o, int ranks) {
  // The points to hand out: all of a plain campaign; of a search, those its plan has decided on so far (replanned
  // whenever a point ends, so that the next values go out as soon as the seeds of the last ones are in).
  auto current = [&] { return base.search ? with_search_points(base, plan_search(base, o.out_dir)) : base; };
  Campaign c = current();
  check_and_record_points(c, o.out_dir);
  std::map<int, std::string> running;  // rank -> the point it runs
  auto pending = [&] {
    std::deque<std::string> todo;
    for (const Point& p : c.points) {
      if (!o.only_point.empty() && p.name != o.only_point) continue;
      const std::string s = read_record(point_dir(o.out_dir, p)).status;
      if (s == "done" || s == "jammed" || (s == "failed" && !o.retry_failed)) continue;
      bool taken = false;
      for (const auto& [rank, name] : running) taken = taken || name == p.name;
      if (!taken) todo.push_back(p.name);
    }
    return todo;
  };
  std::deque<std::string> todo = pending();
  write_table(c, o.out_dir);
  if (!o.quiet)
    std::printf("%zu point(s) to run on %d MPI rank(s)\n", todo.size(), ranks - 1), std::fflush(stdout);
  int outcome = 0, active = ranks - 1;
  std::vector<int> waiting;  // ranks with nothing to do while a search waits for running points
  auto send = [&](int rank, const std::string& next) {
    MPI_Send(next.data(), static_cast<int>(next.size()), MPI_CHAR, rank, tag_point, MPI_COMM_WORLD);
    if (next.empty()) --active;
    else running[rank] = next;
    if (!next.empty() && !o.quiet) std::printf("rank %d: %s\n", rank, next.c_str()), std::fflush(stdout);
  };
  while (active > 0) {
    MPI_Status st = wait_for(MPI_ANY_SOURCE, tag_request);
    int code = 0;
    MPI_Recv(&code, 1, MPI_INT, st.MPI_SOURCE, tag_request, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    running.erase(st.MPI_SOURCE);
    if (code > 128) outcome = code;  // a rank was stopped by a signal: hand out nothing more
    else if (code == exit_numerical_error && outcome == 0) outcome = code;
    if (base.search && code >= 0) {
      c = current();
      check_and_record_points(c, o.out_dir);
    }
    write_table(c, o.out_dir);
    if (code >= 0) todo = pending();
    waiting.push_back(st.MPI_SOURCE);
    // Hand out what there is; idle ranks wait while running points may still call for more; else they stop.
    while (!waiting.empty() && !todo.empty() && outcome <= 128) {
      send(waiting.back(), todo.front());
      waiting.pop_back();
      todo.pop_front();
    }
    if (running.empty() || outcome > 128 || !base.search) {
      for (int rank : waiting) send(rank, "");
      waiting.clear();
    }
  }
  write_table(c, o.out_dir);
  if (!o.quiet) std::printf("table: %s\n", (o.out_dir / "campaign.json").c_str());
  return outcome;
}
}  // namespace

int run_sweep_mpi(const Campaign& c, const SweepOptions& o) {
  MPI_Init(nullptr, nullptr);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int code = 0;
  if (size == 1) code = c.search ? run_search_sweep(c, o) : run_sweep(c, o);
  else if (rank == 0) code = dispatcher(c, o, size);
  else worker(c, o);
  MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Finalize();
  return code;
}
#endif

}  // namespace suspend::campaign
