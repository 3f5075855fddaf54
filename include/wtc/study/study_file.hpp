#pragma once
// Study files (wtc::io): YAML that names scenarios, a base and a reference
// setting, and sweeps (docs/accuracy-study.md). Errors name the file, line
// and column, like every other YAML file of WTC.
#include <filesystem>

#include "wtc/study/study_plan.hpp"

namespace wtc::study {

/// Reads `file` and expands its sweeps into distinct runs. Scene paths are
/// relative to the study file. Throws InvalidInputError naming the place of
/// an unknown key, a missing scene file, an empty sweep, or a sweep value
/// that is neither a list nor a map of labelled values.
study::StudyPlan loadStudyPlan(const std::filesystem::path& file);

}  // namespace wtc::study
