#pragma once
// An experiment's report: every number of its designs and assessments, the statistics AutoMoDe
// papers use, module frequencies and chosen architectures, as one JSON document
// (src/experiments/REPORT_FORMAT.md) — written as CSV files and as a self-contained HTML page
// that the report bundle of the web front end renders offline.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/home.hpp"
#include "storage/accounts.hpp"

namespace sd::app {

/// The report document of a project's experiment (finished or not: what is done so far).
/// NotFound naming the project's experiments when there is no such one.
nlohmann::json experiment_report_document(Home& home, const storage::User& user, const std::string& experiment,
                                          const std::optional<std::string>& project = std::nullopt);

/// The page: the document embedded, rendered by `web_root`/report.js and report.css (the
/// front end's build). Failed when the bundle is missing.
std::string experiment_report_html(const nlohmann::json& document, const std::filesystem::path& web_root);

/// One file of the report's data: report.json or a table's CSV.
struct ReportFile {
  std::string name, content;
};

/// report.json and one CSV per table, as the report folder holds them (what the page points
/// to, served as they are over the web).
std::vector<ReportFile> experiment_report_data_files(const nlohmann::json& document);

/// Writes report.html, report.json and one CSV per table into `folder`; returns the files.
std::vector<std::filesystem::path> write_experiment_report(const nlohmann::json& document,
                                                           const std::filesystem::path& folder,
                                                           const std::filesystem::path& web_root);

}  // namespace sd::app
