#pragma once
// The ranks of a distributed run, as the solver sees them: reductions, an
// exclusive scan and the all-to-all particle exchange. Without MPI initialised
// (unit tests) or on one rank, every call is local and nothing is sent.
#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace ondine {

class Communicator {
 public:
  Communicator();  // MPI_COMM_WORLD when MPI is initialised, a single rank otherwise

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool serial() const { return size_ == 1; }
  MPI_Comm comm() const { return comm_; }

  double sum(double v) const;
  std::int64_t sum(std::int64_t v) const;
  std::uint64_t sum_u64(std::uint64_t v) const;  // modulo 2^64
  double min(double v) const;
  double max(double v) const;
  std::int64_t max(std::int64_t v) const;
  std::int64_t min(std::int64_t v) const;
  bool any(bool v) const { return max(static_cast<std::int64_t>(v)) != 0; }
  void sum_in_place(std::vector<double>& v) const;
  std::int64_t exclusive_scan(std::int64_t v) const;  // sum over lower ranks
  std::vector<std::int64_t> gather_all(std::int64_t v) const;
  // every rank's values, concatenated in rank order (MPI_Allgatherv)
  std::vector<std::int64_t> gather_all(const std::vector<std::int64_t>& v) const;
  std::vector<double> gather_all(const std::vector<double>& v) const;

  // All-to-all of packed particles: `send` holds, rank by rank, send_counts[r]
  // rows of `width` doubles; returns the rows received, rank by rank, with the
  // row count from each rank in recv_counts.
  std::vector<double> exchange(const std::vector<double>& send, const std::vector<int>& send_counts, int width,
                               std::vector<int>& recv_counts) const;
  // Row counts per rank, sent and received (MPI_Alltoall).
  std::vector<int> exchange_counts(const std::vector<int>& send_counts) const;
  // The same with counts already known (a halo refresh): no count exchange.
  void exchange_known(const double* send, const std::vector<int>& send_counts, double* recv,
                      const std::vector<int>& recv_counts, int width) const;
  void barrier() const;
  // `text` of rank `root` on every rank
  std::string broadcast(const std::string& text, int root) const;

 private:
  MPI_Comm comm_ = MPI_COMM_SELF;
  int rank_ = 0, size_ = 1;
};

}  // namespace ondine
