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

/// Loads the scene of every run of `plan` with its overrides (terrain and
/// vehicle built, nothing simulated), so that a study refuses a bad setting
/// before it starts any run. Throws InvalidInputError naming, for each
/// setting refused, the study file's place of the value that is to blame
/// (the sweep's key and value, found by loading the run without it) and the
/// scene's message; or, when no one value is to blame, the run's settings.
void checkStudyRuns(const StudyPlan& plan);

}  // namespace wtc::study
