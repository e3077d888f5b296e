// The stylesheet the report's and the bench's HTML pages share; each page appends its own few rules.
#pragma once

namespace viz::report {

inline constexpr const char* kPageStyle = R"(body{font-family:DejaVu Sans,sans-serif;margin:2em;color:#222;max-width:80em}
table{border-collapse:collapse;margin:0.5em 0 1.5em}td,th{border:1px solid #ccc;padding:0.2em 0.6em;text-align:right}
th{background:#f2f2f2}td.l,th.l{text-align:left}figure{display:inline-block;margin:0.3em;text-align:center;vertical-align:top}
figure img{border:1px solid #ccc}.note{color:#555;font-size:0.9em}.bad{color:#b00}.noisy{color:#a60}
)";

}  // namespace viz::report
