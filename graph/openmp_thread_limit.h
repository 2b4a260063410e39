#pragma once

namespace lrsvo {

// Holds the OpenMP parallel regions the calling thread starts (CHOLMOD's
// supernodal factorisation, Eigen's large products) to a solver's thread
// count while in scope, and gives the caller its own settings back after.
// CHOLMOD asks for a fixed four threads wherever a supernode is large; on
// fewer free cores they spin and wait on one another, which costs more than
// they share (docs/pose_graphs.md). One thread runs every region serially
// (no active parallel level); more set the region size to `threads` and let
// the runtime shrink any region, CHOLMOD's fixed four included, to the
// cores that are free.
class OpenMpThreadLimit {
 public:
  explicit OpenMpThreadLimit(int threads);
  ~OpenMpThreadLimit();
  OpenMpThreadLimit(const OpenMpThreadLimit&) = delete;
  OpenMpThreadLimit& operator=(const OpenMpThreadLimit&) = delete;

 private:
  int maxActiveLevels_;
  int numThreads_;
  int dynamic_;
};

}  // namespace lrsvo
