// OpenBLAS's threads, where it is the BLAS (CHOLMOD's dense blocks): looked up, not linked,
// since the BLAS is whichever libblas.so.3 the system chose; another BLAS is left as it is.
#pragma once

namespace grainmesh {

// Sets OpenBLAS's threads.
void set_blas_threads(int threads);

// OpenBLAS's threads limited to `threads` while it lives. Its threads spin between calls
// (sched_yield) on the cores they share: the two-grid cycles' coarse solves, small
// triangular ones, gain nothing from them and lost the conjugate gradients' second thread
// to them (the 1,000-grain cell's cycles: 3.0 s with them, 2.2 s without).
class BlasThreads {
 public:
  explicit BlasThreads(int threads);
  ~BlasThreads();
  BlasThreads(const BlasThreads&) = delete;
  BlasThreads& operator=(const BlasThreads&) = delete;

 private:
  int before_ = 0;
};

}  // namespace grainmesh
