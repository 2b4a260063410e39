#include "lrsvo/eval/nist_models.h"

#include <cmath>
#include <map>

#include "lrsvo/graph/error.h"

namespace lrsvo {

NistModel nistModelOf(const std::string& datasetName) {
  static const std::map<std::string, NistModel> models = {
      {"Bennett5", NistModel::kBennett5}, {"BoxBOD", NistModel::kMisra1a},    {"Chwirut1", NistModel::kChwirut},
      {"Chwirut2", NistModel::kChwirut},  {"DanWood", NistModel::kDanWood},   {"ENSO", NistModel::kEnso},
      {"Eckerle4", NistModel::kEckerle4}, {"Gauss1", NistModel::kGauss},      {"Gauss2", NistModel::kGauss},
      {"Gauss3", NistModel::kGauss},      {"Hahn1", NistModel::kHahn1},       {"Kirby2", NistModel::kKirby2},
      {"Lanczos1", NistModel::kLanczos},  {"Lanczos2", NistModel::kLanczos},  {"Lanczos3", NistModel::kLanczos},
      {"MGH09", NistModel::kMgh09},       {"MGH10", NistModel::kMgh10},       {"MGH17", NistModel::kMgh17},
      {"Misra1a", NistModel::kMisra1a},   {"Misra1b", NistModel::kMisra1b},   {"Misra1c", NistModel::kMisra1c},
      {"Misra1d", NistModel::kMisra1d},   {"Nelson", NistModel::kNelson},     {"Rat42", NistModel::kRat42},
      {"Rat43", NistModel::kRat43},       {"Roszman1", NistModel::kRoszman1}, {"Thurber", NistModel::kHahn1},
  };
  const auto it = models.find(datasetName);
  if (it != models.end()) return it->second;
  std::string known;
  for (const auto& [name, model] : models) known += (known.empty() ? "" : ", ") + name;
  throw Error("no model for the NIST problem '" + datasetName + "' (known: " + known + ")");
}

double nistResponse(NistModel model, double y) { return model == NistModel::kNelson ? std::log(y) : y; }

}  // namespace lrsvo
