#pragma once
// One MPI job seen from one rank: MPI initialised for the lifetime of the object (funneled: only
// the thread that created it calls MPI), the rank and size, and the collective error protocol
// that keeps a failing rank from leaving the others waiting.
#include <mpi.h>

#include <functional>
#include <string>

namespace raycast::cli::distributed {

class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Collective: every rank passes its own error ("" when it is fine). Returns true when every
  /// rank is fine; otherwise rank 0 prints each distinct error once, with the ranks that had it
  /// ("raycast render: rank 1: scene.yaml:3:7: ..."), and every rank returns false.
  bool agree(const std::string& error, const std::string& command) const;

  /// Prints "<command>: rank R: <message>" and ends the whole job with exit code 2 (MPI_Abort):
  /// for an error after which the ranks can no longer meet in a collective call.
  [[noreturn]] void abort(const std::string& command, const std::string& message) const;

 private:
  int rank_ = 0, size_ = 1;
};

/// Sleeps between polls of something that has not happened yet: 50 microseconds at first, twice as
/// long each time up to 2 ms, so that a quick answer is seen quickly and a long wait (a frame
/// that takes a minute) costs a few hundred wake-ups a second, not thousands.
class IdleBackoff {
 public:
  void pause();
  void reset() { delay_ = kShortest; }

 private:
  static constexpr long kShortest = 50, kLongest = 2000;  // microseconds
  long delay_ = kShortest;
};

/// Waits for a non-blocking MPI request without spinning. OpenMPI's blocking calls poll at 100%
/// CPU while they wait (for the next order, for a slower rank at the end of the job), which takes
/// the core from a renderer sharing it.
void wait_idle(MPI_Request& request);

/// Collective: returns once every rank has called it, waiting as wait_idle does.
void barrier_idle();

/// Runs body on this rank inside an MPI session; an exception that escapes it is reported with
/// the rank and aborts the whole job (exit code 2), so that no other rank waits forever.
/// `command` prefixes the messages ("raycast render").
int run_distributed(const std::string& command, const std::function<int(MpiSession&)>& body);

}  // namespace raycast::cli::distributed
