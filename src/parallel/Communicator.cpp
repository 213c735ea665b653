#include "parallel/Communicator.hpp"

#include <algorithm>
#include <stdexcept>

namespace ondine {

Communicator::Communicator() {
  int init = 0, fin = 0;
  MPI_Initialized(&init);
  MPI_Finalized(&fin);
  if (init && !fin) {
    comm_ = MPI_COMM_WORLD;
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
  }
}

namespace {
template <class T>
T reduce(MPI_Comm c, int size, T v, MPI_Datatype t, MPI_Op op) {
  if (size == 1) return v;
  T out{};
  MPI_Allreduce(&v, &out, 1, t, op, c);
  return out;
}
}  // namespace

double Communicator::sum(double v) const { return reduce(comm_, size_, v, MPI_DOUBLE, MPI_SUM); }
std::int64_t Communicator::sum(std::int64_t v) const { return reduce(comm_, size_, v, MPI_INT64_T, MPI_SUM); }
std::uint64_t Communicator::sum_u64(std::uint64_t v) const { return reduce(comm_, size_, v, MPI_UINT64_T, MPI_SUM); }
double Communicator::min(double v) const { return reduce(comm_, size_, v, MPI_DOUBLE, MPI_MIN); }
double Communicator::max(double v) const { return reduce(comm_, size_, v, MPI_DOUBLE, MPI_MAX); }
std::int64_t Communicator::max(std::int64_t v) const { return reduce(comm_, size_, v, MPI_INT64_T, MPI_MAX); }
std::int64_t Communicator::min(std::int64_t v) const { return reduce(comm_, size_, v, MPI_INT64_T, MPI_MIN); }

void Communicator::sum_in_place(std::vector<double>& v) const {
  if (size_ == 1 || v.empty()) return;
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm_);
}

std::int64_t Communicator::exclusive_scan(std::int64_t v) const {
  if (size_ == 1) return 0;
  std::int64_t out = 0;
  MPI_Exscan(&v, &out, 1, MPI_INT64_T, MPI_SUM, comm_);
  return rank_ == 0 ? 0 : out;
}

std::vector<std::int64_t> Communicator::gather_all(std::int64_t v) const {
  std::vector<std::int64_t> out(size_, v);
  if (size_ > 1) MPI_Allgather(&v, 1, MPI_INT64_T, out.data(), 1, MPI_INT64_T, comm_);
  return out;
}

namespace {
template <class T>
std::vector<T> all_gather_v(const std::vector<T>& v, MPI_Datatype type, int size, MPI_Comm comm) {
  if (size == 1) return v;
  const int mine = static_cast<int>(v.size());
  std::vector<int> counts(size), displs(size);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < size; ++r) {
    displs[r] = total;
    total += counts[r];
  }
  std::vector<T> out(static_cast<std::size_t>(total));
  MPI_Allgatherv(v.data(), mine, type, out.data(), counts.data(), displs.data(), type, comm);
  return out;
}
}  // namespace

std::vector<std::int64_t> Communicator::gather_all(const std::vector<std::int64_t>& v) const {
  return all_gather_v(v, MPI_INT64_T, size_, comm_);
}

std::vector<double> Communicator::gather_all(const std::vector<double>& v) const {
  return all_gather_v(v, MPI_DOUBLE, size_, comm_);
}

void Communicator::exchange_known(const double* send, const std::vector<int>& send_counts, double* recv,
                                  const std::vector<int>& recv_counts, int width) const {
  if (size_ == 1) {
    std::copy(send, send + static_cast<std::size_t>(send_counts[0]) * width, recv);
    return;
  }
  std::vector<int> sc(size_), sd(size_), rc(size_), rd(size_);
  long long s = 0, r = 0;
  for (int k = 0; k < size_; ++k) {
    sc[k] = send_counts[k] * width;
    rc[k] = recv_counts[k] * width;
    sd[k] = static_cast<int>(s);
    rd[k] = static_cast<int>(r);
    s += sc[k];
    r += rc[k];
  }
  if (s > 2147483647LL || r > 2147483647LL) throw std::runtime_error("particle exchange larger than 2^31 values");
  MPI_Alltoallv(send, sc.data(), sd.data(), MPI_DOUBLE, recv, rc.data(), rd.data(), MPI_DOUBLE, comm_);
}

std::vector<double> Communicator::exchange(const std::vector<double>& send, const std::vector<int>& send_counts, int width,
                                           std::vector<int>& recv_counts) const {
  recv_counts.assign(size_, 0);
  if (size_ == 1) {
    recv_counts[0] = send_counts[0];
    return send;
  }
  recv_counts = exchange_counts(send_counts);
  long long total = 0;
  for (int c : recv_counts) total += c;
  std::vector<double> recv(static_cast<std::size_t>(total) * width);
  exchange_known(send.data(), send_counts, recv.data(), recv_counts, width);
  return recv;
}

std::vector<int> Communicator::exchange_counts(const std::vector<int>& send_counts) const {
  if (size_ == 1) return send_counts;
  std::vector<int> recv(size_, 0);
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv.data(), 1, MPI_INT, comm_);
  return recv;
}

std::string Communicator::broadcast(const std::string& text, int root) const {
  if (size_ == 1) return text;
  int n = static_cast<int>(text.size());
  MPI_Bcast(&n, 1, MPI_INT, root, comm_);
  std::string out = rank_ == root ? text : std::string(n, ' ');
  if (n > 0) MPI_Bcast(&out[0], n, MPI_CHAR, root, comm_);
  return out;
}

void Communicator::barrier() const {
  if (size_ > 1) MPI_Barrier(comm_);
}

}  // namespace ondine
