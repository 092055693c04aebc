#include "analysis/blas_threads.hpp"

#include <dlfcn.h>

namespace grainmesh {

void set_blas_threads(int threads) {
  using Set = void (*)(int);
  if (auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(threads);
}

BlasThreads::BlasThreads(int threads) {
  using Get = int (*)();
  if (auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"))) {
    before_ = get();
    set_blas_threads(threads);
  }
}

BlasThreads::~BlasThreads() {
  if (before_ > 0) set_blas_threads(before_);
}

}  // namespace grainmesh
