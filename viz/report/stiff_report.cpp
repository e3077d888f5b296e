// The stiff suite's files: stiff.csv and a static stiff.html table of cases x techniques.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "report/report_table.h"
#include "report/stiff_suite.h"
#include "report/text_output.h"

namespace viz::report {

namespace {
std::string stiffFigure(double v) { return formatFigure(v, "%.4g"); }
}  // namespace

void writeStiffFiles(const std::string& folder, const ReportMeta& meta, const std::vector<StiffOutcome>& outcomes) {
    std::ostringstream csv;
    csv << "case,class,technique,passed,ran,relative_l2,bound,max_abs,nan_pixels,inf_pixels,negative_pixels,ms,verdict\n";
    for (const StiffOutcome& o : outcomes)
        csv << csvField(o.caseId) << "," << o.caseClass << "," << o.technique << "," << (o.passed ? 1 : 0) << ","
            << (o.ran ? 1 : 0) << "," << stiffFigure(o.error.relativeL2) << ","
            << (o.bound ? stiffFigure(o.bound->relativeL2) : "") << "," << stiffFigure(o.error.maxAbsolute) << ","
            << o.error.nanPixels << "," << o.error.infPixels << "," << o.error.negativePixels << ","
            << stiffFigure(o.milliseconds) << "," << csvField(o.verdict) << "\n";
    writeTextFile((std::filesystem::path(folder) / "stiff.csv").string(), csv.str());

    std::vector<std::string> cases, techniques;
    for (const StiffOutcome& o : outcomes) {
        if (std::find(cases.begin(), cases.end(), o.caseId) == cases.end()) cases.push_back(o.caseId);
        if (std::find(techniques.begin(), techniques.end(), o.technique) == techniques.end())
            techniques.push_back(o.technique);
    }
    std::size_t failures = 0;
    for (const StiffOutcome& o : outcomes) failures += !o.passed;
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Airlight stiff cases</title><style>"
         "body{font-family:DejaVu Sans,sans-serif;margin:2em;color:#222}table{border-collapse:collapse}"
         "td,th{border:1px solid #ccc;padding:0.2em 0.5em;vertical-align:top}th{background:#f2f2f2}"
         ".pass{background:#e8f5e9}.fail{background:#fde0dc}.note{color:#555;font-size:0.85em}</style></head><body>\n"
      << "<h1>Stiff and extreme cases</h1>\n<p class=\"note\">" << escapeHtml(meta.date) << " &middot; "
      << escapeHtml(meta.machine) << " &middot; " << escapeHtml(meta.renderer) << "<br>Each technique runs at its stiff-suite "
         "settings; a cell passes when every pixel is finite and non-negative and the relative L2 error of L_air "
         "against the reference is within the bound the technique declares for the case's class (or it refuses "
         "a class it declares it cannot handle). "
      << failures << " of " << outcomes.size() << " cells fail.</p>\n<table><tr><th>case</th><th>class</th>";
    for (const std::string& t : techniques) h << "<th>" << escapeHtml(t) << "</th>";
    h << "</tr>\n";
    for (const std::string& c : cases) {
        const StiffOutcome* first = nullptr;
        for (const StiffOutcome& o : outcomes)
            if (o.caseId == c) {
                first = &o;
                break;
            }
        h << "<tr><td>" << escapeHtml(c) << "</td><td>" << escapeHtml(first->caseClass) << "</td>";
        for (const std::string& t : techniques) {
            const StiffOutcome* cell = nullptr;
            for (const StiffOutcome& o : outcomes)
                if (o.caseId == c && o.technique == t) cell = &o;
            if (!cell) {
                h << "<td></td>";
                continue;
            }
            h << "<td class=\"" << (cell->passed ? "pass" : "fail") << "\">" << (cell->passed ? "pass" : "FAIL")
              << "<br><span class=\"note\">" << escapeHtml(cell->verdict) << "</span></td>";
        }
        h << "</tr>\n";
    }
    h << "</table>\n</body></html>\n";
    writeTextFile((std::filesystem::path(folder) / "stiff.html").string(), h.str());
}

}  // namespace viz::report
