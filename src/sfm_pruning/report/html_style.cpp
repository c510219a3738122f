#include "sfm_pruning/report/html_style.hpp"

namespace sfm_pruning {

const char* const kReportCss = R"CSS(
:root { --ink: #1d2230; --muted: #5b6270; --line: #d9dde3; --panel: #ffffff; --bg: #f3f4f7; }
* { box-sizing: border-box; }
body { margin: 0; background: var(--bg); color: var(--ink);
       font: 14px/1.45 "DejaVu Sans", "Segoe UI", Helvetica, Arial, sans-serif; }
header { background: #1d2230; color: #fff; padding: 22px 36px 18px; }
header h1 { margin: 0 0 4px; font-size: 24px; font-weight: 600; letter-spacing: .2px; }
header .sub { color: #b9c0cc; font-size: 13px; }
header nav { margin-top: 10px; font-size: 13px; }
header nav a { color: #dfe5ee; text-decoration: none; margin-right: 18px; border-bottom: 1px dotted #7d8696; }
main { max-width: 1180px; margin: 0 auto; padding: 18px 24px 40px; }
section { background: var(--panel); border: 1px solid var(--line); border-radius: 8px;
          padding: 16px 20px 18px; margin: 16px 0; }
h2 { font-size: 17px; margin: 0 0 4px; font-weight: 600; }
p.note { color: var(--muted); margin: 2px 0 12px; font-size: 13px; }
.cols { display: grid; grid-template-columns: repeat(auto-fit, minmax(420px, 1fr)); gap: 18px; }
.col h3 { font-size: 14px; margin: 4px 0 8px; font-weight: 600; }
.tag { display: inline-block; padding: 1px 8px; border-radius: 10px; font-size: 12px; color: #fff;
       vertical-align: 1px; margin-left: 6px; }
svg { width: 100%; height: auto; display: block; }
svg text { font: 12px "DejaVu Sans", Helvetica, Arial, sans-serif; fill: var(--ink); }
svg text.value { fill: var(--muted); font-size: 11px; }
svg text.total { font-weight: 600; }
.cards { display: grid; grid-template-columns: repeat(auto-fit, minmax(150px, 1fr)); gap: 10px; }
.card { border: 1px solid var(--line); border-radius: 6px; padding: 8px 12px; background: #fbfbfc; }
.card .k { color: var(--muted); font-size: 12px; }
.card .v { font-size: 20px; font-weight: 600; }
.card .v.text { font-size: 15px; padding-top: 4px; overflow-wrap: anywhere; }
.card .v small { font-size: 12px; color: var(--muted); font-weight: 400; }
table { border-collapse: collapse; width: 100%; font-size: 13px; }
th, td { text-align: left; padding: 5px 10px; border-bottom: 1px solid var(--line); }
th { color: var(--muted); font-weight: 600; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
.swatch { display: inline-block; width: 11px; height: 11px; border-radius: 50%; vertical-align: -1px;
          margin-right: 6px; }
.legend { display: flex; flex-wrap: wrap; gap: 6px 18px; color: var(--muted); font-size: 12px; margin: 8px 0 0; }
.legend .line { display: inline-block; width: 22px; height: 0; border-top: 2px solid; vertical-align: 3px;
                margin-right: 6px; }
.legend .dashed { border-top-style: dashed; }
.check img { width: 100%; height: auto; border: 1px solid var(--line); border-radius: 4px; display: block; }
.check { margin: 10px 0 18px; }
.check h3 { font-size: 14px; margin: 0 0 6px; }
label.toggle { font-size: 13px; color: var(--muted); cursor: pointer; user-select: none; }
.hide-removed .removed-edges { display: none; }
footer { color: var(--muted); font-size: 12px; text-align: center; padding: 8px 0 24px; }
code { font-size: 12px; background: #eef0f4; padding: 1px 4px; border-radius: 3px; }
)CSS";

const char* const kReportScript = R"JS(
(function () {
  'use strict';
  var toggle = document.getElementById('show-removed');
  if (!toggle) { return; }
  toggle.addEventListener('change', function () {
    document.body.classList.toggle('hide-removed', !toggle.checked);
  });
})();
)JS";

}  // namespace sfm_pruning
