#include "lrsvo/vertices/vertex_bal_camera.h"

namespace lrsvo {}  // namespace lrsvo
