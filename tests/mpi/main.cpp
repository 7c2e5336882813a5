// The distributed-engine tests: every rank runs every test (mpirun -n 1, 2, 4); a rank's
// failure fails its process and so the run. Only rank 0 prints.
#include <gtest/gtest.h>

#include "talus/parallel/communicator.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const talus::Communicator& comm = talus::Communicator::world();
  if (comm.rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
