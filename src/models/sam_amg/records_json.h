#pragma once
// Reading and writing AMG records in the JSON layout of the SAM fixtures (`levels` =
// {"default": [...], "s": [...], "m": [...], "l": [...]}, records with an uncompressed RLE).
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "models/sam_amg/automatic_mask_generator.h"
#include "models/sam_amg/mask_record.h"

namespace cls::amg {

// `where` names the source in error messages (file path). Throws cls::Error on a bad layout.
MaskRecord record_from_json(const nlohmann::json& j, const std::string& where);
nlohmann::json record_to_json(const MaskRecord& r);
MaskLevels levels_from_json(const nlohmann::json& levels, const std::string& where);
nlohmann::json levels_to_json(const MaskLevels& levels);
// Reads the `levels` object of a records or post JSON file.
MaskLevels read_levels_file(const std::string& path);
// The generator's parameters as the fixture's records files store them (`params`: the
// SamAutomaticMaskGenerator arguments by name, every one required).
AmgParams params_from_json(const nlohmann::json& params, const std::string& where);

}  // namespace cls::amg
