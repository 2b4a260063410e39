#include "lrsvo/frontend/datasets/source_factory.h"

#include <filesystem>

#include "lrsvo/frontend/datasets/euroc_reader.h"
#include "lrsvo/frontend/datasets/kitti_reader.h"
#include "lrsvo/graph/error.h"

namespace lrsvo {

std::unique_ptr<FrameSource> openDatasetSource(const std::string& spec) {
  namespace fs = std::filesystem;
  if (spec.starts_with("euroc:")) return std::make_unique<EurocSource>(spec.substr(6));
  if (spec.starts_with("kitti:")) return std::make_unique<KittiSource>(spec.substr(6));
  if (!fs::is_directory(spec))
    throw Error("data set '" + spec + "': not a directory (expected DIR, euroc:DIR or kitti:DIR)");
  if (fs::is_directory(fs::path(spec) / "mav0")) return std::make_unique<EurocSource>(spec);
  if (fs::exists(fs::path(spec) / "calib.txt") && fs::is_directory(fs::path(spec) / "image_0"))
    return std::make_unique<KittiSource>(spec);
  throw Error("data set '" + spec + "': neither EuRoC (DIR/mav0) nor KITTI (DIR/calib.txt and DIR/image_0)");
}

}  // namespace lrsvo
