// `mpirun -np N raycast cast SCENE --binary --rays IN -o OUT`: rank r answers the r-th of N
// contiguous slices of the ray records and writes its answers at their place in OUT with MPI-IO,
// so that OUT is byte for byte the single-process output and no rank holds more than its slice.
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>

#include "distributed/distributed.h"
#include "distributed/mpi_session.h"
#include "load/loader.h"

namespace raycast::cli::distributed {

namespace {

const char* const kCastCommand = "raycast cast";
constexpr long long kRecordIn = 64;      // 8 float64 per ray
constexpr long long kChunk = 1 << 20;    // rays read, answered and written at a time (64 MiB)
constexpr long long kPiece = 1LL << 30;  // MPI counts are int: at most this per call

std::string mpi_error(int code) {
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  return std::string(text, std::size_t(length));
}

void read_at(MPI_File file, long long offset, std::string& bytes, const std::string& path) {
  for (long long done = 0; done < static_cast<long long>(bytes.size());) {
    const int count = int(std::min<long long>(kPiece, static_cast<long long>(bytes.size()) - done));
    const int rc = MPI_File_read_at(file, offset + done, bytes.data() + done, count, MPI_CHAR,
                                    MPI_STATUS_IGNORE);
    if (rc != MPI_SUCCESS) throw std::runtime_error(path + ": cannot read: " + mpi_error(rc));
    done += count;
  }
}

void write_at(MPI_File file, long long offset, const std::string& bytes, const std::string& path) {
  for (long long done = 0; done < static_cast<long long>(bytes.size());) {
    const int count = int(std::min<long long>(kPiece, static_cast<long long>(bytes.size()) - done));
    const int rc = MPI_File_write_at(file, offset + done, bytes.data() + done, count, MPI_CHAR,
                                     MPI_STATUS_IGNORE);
    if (rc != MPI_SUCCESS) throw std::runtime_error(path + ": cannot write: " + mpi_error(rc));
    done += count;
  }
}

/// Collective open; the error of this rank, or "" (files report errors, they do not abort).
std::string open(const std::string& path, int mode, MPI_File& file, const char* what) {
  const int rc = MPI_File_open(MPI_COMM_WORLD, path.c_str(), mode, MPI_INFO_NULL, &file);
  if (rc == MPI_SUCCESS) return "";
  file = MPI_FILE_NULL;
  return path + ": cannot open the " + what + ": " + mpi_error(rc);
}

}  // namespace

int cast(const std::string& scene_path, const std::string& rays, const std::string& output,
         const CastOptions& options) {
  return run_distributed(kCastCommand, [&](MpiSession& session) {
    if (!options.binary || rays.empty() || output.empty()) {
      if (session.rank() == 0)
        std::fprintf(stderr,
                     "%s: under mpirun, cast needs --binary, --rays FILE and -o FILE (each rank "
                     "reads its slice of the rays and writes its answers in place)\n",
                     kCastCommand);
      return 2;
    }
    std::optional<Scene> scene;
    std::string error;
    try {
      scene = load_scene_file(scene_path);
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (!session.agree(error, kCastCommand)) return 2;

    MPI_File in = MPI_FILE_NULL, out = MPI_FILE_NULL;
    error = open(rays, MPI_MODE_RDONLY, in, "ray file");
    const std::string out_error = open(output, MPI_MODE_CREATE | MPI_MODE_WRONLY, out, "output");
    if (error.empty()) error = out_error;
    if (!session.agree(error, kCastCommand)) {
      if (in != MPI_FILE_NULL) MPI_File_close(&in);
      if (out != MPI_FILE_NULL) MPI_File_close(&out);
      return 2;
    }

    MPI_Offset size = 0;
    MPI_File_get_size(in, &size);
    const long long records = size / kRecordIn, tail = size % kRecordIn;
    const int rank = session.rank(), ranks = session.size();
    const long long lo = records * rank / ranks, hi = records * (rank + 1) / ranks;
    const bool last = rank == ranks - 1;
    // Fixed-size answers go straight to their place; --all answers vary in length, so a rank
    // keeps its slice's answers until the exclusive prefix sum of the lengths gives its offset.
    const long long record_out = options.mode == CastMode::kNearest ? 11 * 8
                                 : options.mode == CastMode::kAny   ? 8
                                                                    : 0;
    std::string variable;
    CastOptions slice = options;
    slice.source = rays;
    try {
      // The last rank also reads a truncated last record, so that it is reported as without MPI.
      bool tail_pending = last && tail > 0;
      for (long long at = lo; at < hi || tail_pending;) {
        const long long n = std::min(kChunk, hi - at);
        const bool with_tail = tail_pending && at + n == hi;
        std::string bytes(std::size_t(n * kRecordIn + (with_tail ? tail : 0)), '\0');
        read_at(in, at * kRecordIn, bytes, rays);
        std::istringstream chunk_in(std::move(bytes));
        std::ostringstream chunk_out;
        slice.first_record = at;
        run_cast(*scene, chunk_in, chunk_out, slice);
        if (record_out > 0)
          write_at(out, at * record_out, chunk_out.str(), output);
        else
          variable += chunk_out.str();
        at += n;
        if (with_tail) tail_pending = false;
      }
    } catch (const std::exception& e) {
      error = e.what();
    }
    long long total = records * record_out;
    if (record_out == 0) {
      long long mine = static_cast<long long>(variable.size()), offset = 0;
      MPI_Request requests[2];
      MPI_Iexscan(&mine, &offset, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD, &requests[0]);
      MPI_Iallreduce(&mine, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD, &requests[1]);
      wait_idle(requests[0]);
      wait_idle(requests[1]);
      if (rank == 0) offset = 0;  // MPI_Exscan leaves rank 0's result undefined
      try {
        if (error.empty()) write_at(out, offset, variable, output);
      } catch (const std::exception& e) {
        error = e.what();
      }
    }
    barrier_idle();                 // the collective file calls below then wait for nobody
    MPI_File_set_size(out, total);  // collective: cuts what an older, longer file had beyond
    MPI_File_close(&in);
    MPI_File_close(&out);
    if (!session.agree(error, kCastCommand)) return 2;
    if (rank == 0)
      std::fprintf(stderr, "%s: %lld rays answered on %d ranks -> %s\n", kCastCommand, records,
                   ranks, output.c_str());
    return 0;
  });
}

}  // namespace raycast::cli::distributed
