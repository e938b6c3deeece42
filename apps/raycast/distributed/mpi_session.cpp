#include "distributed/mpi_session.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <new>
#include <stdexcept>
#include <thread>
#include <vector>

namespace raycast::cli::distributed {

namespace {

/// "0" / "0-3" / "0, 2, 5" for the ranks that reported one error.
std::string rank_list(const std::vector<int>& ranks) {
  std::string text = ranks.size() > 1 ? "ranks " : "rank ";
  bool consecutive = ranks.size() > 2;
  for (std::size_t i = 1; i < ranks.size(); ++i) consecutive &= ranks[i] == ranks[i - 1] + 1;
  if (consecutive) return text + std::to_string(ranks.front()) + "-" + std::to_string(ranks.back());
  for (std::size_t i = 0; i < ranks.size(); ++i) text += (i ? ", " : "") + std::to_string(ranks[i]);
  return text;
}

}  // namespace

MpiSession::MpiSession() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  // Rank 0 renders on a second thread that never calls MPI: funneled is all it needs.
  if (provided < MPI_THREAD_FUNNELED) abort("raycast", "MPI does not provide MPI_THREAD_FUNNELED");
}

MpiSession::~MpiSession() { MPI_Finalize(); }

bool MpiSession::agree(const std::string& error, const std::string& command) const {
  int mine = error.empty() ? 0 : 1, failures = 0;
  MPI_Request request;
  MPI_Iallreduce(&mine, &failures, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD, &request);
  wait_idle(request);
  if (failures == 0) return true;
  // Gather every rank's message at rank 0 (lengths, then the bytes).
  int length = int(error.size());
  std::vector<int> lengths(rank_ == 0 ? size_ : 0), offsets(lengths.size());
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    offsets[r] = total;
    total += lengths[r];
  }
  std::vector<char> all(std::size_t(total) + 1);
  MPI_Gatherv(error.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              0, MPI_COMM_WORLD);
  if (rank_ == 0) {
    // The same error on every rank (a syntax error in the scene) is printed once.
    std::map<std::string, std::vector<int>> by_message;
    std::vector<std::string> order;
    for (int r = 0; r < size_; ++r) {
      if (lengths[r] == 0) continue;
      const std::string message(all.data() + offsets[r], std::size_t(lengths[r]));
      if (by_message[message].empty()) order.push_back(message);
      by_message[message].push_back(r);
    }
    for (const std::string& message : order)
      std::fprintf(stderr, "%s: %s: %s\n", command.c_str(), rank_list(by_message[message]).c_str(),
                   message.c_str());
    std::fflush(stderr);
  }
  return false;
}

void MpiSession::abort(const std::string& command, const std::string& message) const {
  std::fprintf(stderr, "%s: rank %d: %s\n", command.c_str(), rank_, message.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 2);
  std::_Exit(2);  // MPI_Abort does not return; in case an implementation does
}

void IdleBackoff::pause() {
  std::this_thread::sleep_for(std::chrono::microseconds(delay_));
  delay_ = std::min(2 * delay_, kLongest);
}

void wait_idle(MPI_Request& request) {
  IdleBackoff backoff;
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    backoff.pause();
  }
}

void barrier_idle() {
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  wait_idle(request);
}

int run_distributed(const std::string& command, const std::function<int(MpiSession&)>& body) {
  MpiSession session;
  try {
    return body(session);
  } catch (const std::bad_alloc&) {
    session.abort(command, "out of memory");
  } catch (const std::exception& e) {
    session.abort(command, e.what());
  }
}

}  // namespace raycast::cli::distributed
