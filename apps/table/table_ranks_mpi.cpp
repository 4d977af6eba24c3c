#include "table_ranks_mpi.hpp"

#include <memory>
#include <string>

#include <mpi.h>

#include "table_ranks.hpp"

namespace dc::table {
namespace {

constexpr int kTagResult = 1;  // rank -> 0: {"unit": u, "result": r} (u = -1: first request)
constexpr int kTagAssign = 2;  // 0 -> rank: the next unit, -1: stop

class MpiRanks final : public RankTransport {
 public:
  LaunchRank start() override {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    LaunchRank joined;
    MPI_Comm_rank(MPI_COMM_WORLD, &joined.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &joined.size);
    return joined;
  }

  /// Rank 0: answers pending requests (storing the results they carry) without blocking.
  /// Returns the number of ranks that were told to stop.
  int serve(const std::function<long long()>& next_unit,
            const std::function<void(std::size_t, const std::string&)>& store) override {
    int stopped = 0;
    for (;;) {
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &status);
      if (!flag) return stopped;
      int size = 0;
      MPI_Get_count(&status, MPI_CHAR, &size);
      std::string text(static_cast<std::size_t>(size), '\0');
      MPI_Recv(text.data(), size, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const nlohmann::json message = nlohmann::json::parse(text);
      const long long unit = message.at("unit").get<long long>();
      if (unit >= 0) store(static_cast<std::size_t>(unit), message.at("result").dump());
      long long next = next_unit();
      MPI_Send(&next, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD);
      if (next < 0) ++stopped;
    }
  }

  /// Ranks other than 0: ask for a unit, solve it, send its result with the next request.
  void work(const std::function<nlohmann::json(std::size_t)>& result) override {
    nlohmann::json message = {{"unit", -1}};
    for (;;) {
      const std::string text = message.dump();
      MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
      long long unit = -1;
      MPI_Recv(&unit, 1, MPI_LONG_LONG, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (unit < 0) return;
      message = {{"unit", unit}, {"result", result(static_cast<std::size_t>(unit))}};
    }
  }

  void finish() override { MPI_Finalize(); }
};

}  // namespace

void use_mpi_ranks() { install_rank_transport(std::make_unique<MpiRanks>()); }

}  // namespace dc::table
