#pragma once
// The one JSON form of requests and reports (keys in snake_case, as the CLI's options). Requests
// carry their kind: {"kind": "render", "sdf": "Torus", "output": "t.png", "shading": {...}, ...};
// absent keys keep their defaults, unknown keys are errors that name them. Reports are what
// `--json` prints; reading one back ignores keys it does not know (reports grow).

#include <values/Requests.h>

#include <core/Expected.h>

#include <string>

namespace sdfwb::jobs {

// One line when `indent` < 0, else pretty-printed with that many spaces.
std::string toJson(const values::Request& request, int indent = -1);
// Any kind, chosen by "kind". Errors name the key: "render request: 'width': expected an integer".
Expected<values::Request> requestFromJson(const std::string& text);

std::string toJson(const values::RenderReport& report, int indent = 2);
std::string toJson(const values::AnimateReport& report, int indent = 2);
std::string toJson(const values::SampleReport& report, int indent = 2);
std::string toJson(const values::MergeReport& report, int indent = 2);
std::string toJson(const values::AuditJobReport& report, int indent = 2);
std::string toJson(const values::ListReport& report, int indent = 2);
std::string toJson(const values::BenchReport& report, int indent = 2);
std::string toJson(const values::ParamsReport& report, int indent = 2);
std::string toJson(const values::MeshReport& report, int indent = 2);
std::string toJson(const values::EvalReport& report, int indent = 2);
std::string toJson(const values::RunReport& report, int indent = 2);
std::string toJson(const values::ProbeReport& report, int indent = 2);
// One item's outcome; with indent -1 the status file's line.
std::string toJson(const values::RunItemReport& report, int indent = 2);

// The dataset report's measurements (dataset/report.json, as scripts/dataset_report.py writes it)
// added to the items of the same name, and its machine and date into the report.
Expected<void> addDatasetMeasurements(const std::string& reportText, values::ListReport& report);

// Reads a report of type T (one of the reports above) back from toJson's text.
template <class T> Expected<T> reportFromJson(const std::string& text);

} // namespace sdfwb::jobs
