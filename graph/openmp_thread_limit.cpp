#include "lrsvo/graph/openmp_thread_limit.h"

#include <omp.h>

namespace lrsvo {

OpenMpThreadLimit::OpenMpThreadLimit(int threads)
    : maxActiveLevels_(omp_get_max_active_levels()), numThreads_(omp_get_max_threads()), dynamic_(omp_get_dynamic()) {
  if (threads <= 1) {
    omp_set_max_active_levels(0);
    return;
  }
  omp_set_num_threads(threads);
  omp_set_dynamic(1);
}

OpenMpThreadLimit::~OpenMpThreadLimit() {
  omp_set_max_active_levels(maxActiveLevels_);
  omp_set_num_threads(numThreads_);
  omp_set_dynamic(dynamic_);
}

}  // namespace lrsvo
