"""The report's inline stylesheet and its one optional script (no external resources)."""

from __future__ import annotations

import base64
import hashlib

STYLE = """
:root{--fg:#1f2328;--muted:#59636e;--line:#d1d9e0;--bg:#ffffff;--soft:#f6f8fa;
--err:#cf222e;--warn:#9a6700;--info:#0969da;--ok:#1a7f37;--lc:#8250df;
--mono:ui-monospace,"SFMono-Regular","DejaVu Sans Mono",Menlo,Consolas,monospace;
--sans:system-ui,-apple-system,"Segoe UI",Roboto,"Noto Sans","DejaVu Sans",sans-serif}
*{box-sizing:border-box}
body{margin:0;font:14px/1.45 var(--sans);color:var(--fg);background:var(--bg)}
header.top{display:flex;align-items:baseline;gap:24px;padding:10px 20px;
border-bottom:1px solid var(--line);background:var(--soft);position:sticky;top:0;z-index:2}
header.top h1{font-size:18px;margin:0}
nav a{margin-right:14px;color:var(--info);text-decoration:none}
main{padding:6px 20px 30px;max-width:1420px}
footer{padding:10px 20px;color:var(--muted);font-size:12px}
h2{font-size:17px;margin:20px 0 8px;padding-bottom:4px;border-bottom:1px solid var(--line)}
h3{font-size:14px;margin:14px 0 6px}
code,pre{font-family:var(--mono);font-size:12px}
a{color:var(--info)}
.cards{display:flex;flex-wrap:wrap;gap:10px;margin:12px 0}
.card{border:1px solid var(--line);border-radius:6px;padding:6px 14px;min-width:92px;
background:var(--bg)}
.card .value{display:block;font-size:22px;font-weight:600}
.card .label{color:var(--muted);font-size:12px}
.card.ok .value{color:var(--ok)}.card.bad .value{color:var(--err)}
.card.sev-card-error .value{color:var(--err)}.card.sev-card-warning .value{color:var(--warn)}
.card.sev-card-info .value{color:var(--info)}
ul.rules{list-style:none;padding:0;margin:4px 0;display:flex;flex-wrap:wrap;gap:6px 16px}
ul.rules a{text-decoration:none;color:var(--fg)}
p.roots,details.roots summary{margin:6px 0 2px;color:var(--muted);font-weight:400}
ul.roots{margin:2px 0;padding-left:20px;columns:2}
.sev{display:inline-block;font-size:11px;font-weight:600;border-radius:10px;padding:0 7px;
color:#fff;text-decoration:none;vertical-align:1px}
.sev-error{background:var(--err)}.sev-warning{background:var(--warn)}.sev-info{background:var(--info)}
.slug{color:var(--muted)}
.count{display:inline-block;background:var(--soft);border:1px solid var(--line);
border-radius:10px;padding:0 7px;font-size:11px;font-weight:400}
table{border-collapse:collapse;width:100%;margin:4px 0 10px;font-size:13px}
th,td{border-bottom:1px solid var(--line);padding:3px 8px;text-align:left;vertical-align:top}
th{background:var(--soft);font-weight:600}
table.index td.where,table.index td.rule{white-space:nowrap;width:1%}
table.index tbody{border-top:2px solid var(--line)}
.loc{font-family:var(--mono);font-size:12px;color:var(--muted)}
a .loc{color:var(--info)}
article.finding{border:1px solid var(--line);border-left:4px solid var(--line);
border-radius:6px;padding:8px 12px;margin:8px 0;background:var(--bg)}
article.sev-error{border-left-color:var(--err)}article.sev-warning{border-left-color:var(--warn)}
article.sev-info{border-left-color:var(--info)}
article:target{box-shadow:0 0 0 3px #54aeff66}
article header .code{font-weight:700;font-size:13px}
p.msg{margin:4px 0 6px;font-weight:500}
pre.frame{background:var(--soft);border:1px solid var(--line);border-radius:4px;margin:4px 0;
padding:6px 0;overflow-x:auto;tab-size:4}
pre.frame .row{display:inline-block;min-width:100%;padding:0 10px;white-space:pre}
pre.frame .row.hit{background:#fff8c5}
pre.frame .ln{display:inline-block;color:var(--muted);margin-right:12px;user-select:none}
pre.frame mark{background:#ffd33d99;color:inherit;border-bottom:2px solid var(--err);
border-radius:2px}
.part h4{margin:6px 0 2px;font-size:12px;color:var(--muted);text-transform:uppercase;
letter-spacing:.04em}
.part ol,.part ul{margin:2px 0;padding-left:22px}
code.snippet{color:var(--muted)}
ul.witness{list-style:none;padding:0;display:flex;gap:8px}
ul.witness code{background:var(--soft);border:1px solid var(--line);border-radius:4px;
padding:0 5px}
.stats{margin:4px 0 6px}
.note{color:var(--warn)}
.clean{color:var(--ok);font-weight:600}
ul.legend{list-style:none;padding:0;margin:6px 0;display:flex;flex-wrap:wrap;gap:4px 18px;
font-size:12px;color:var(--muted)}
.sw{display:inline-block;width:22px;height:12px;border-radius:3px;border:1px solid #8c959f;
background:#fff;vertical-align:-1px;margin-right:5px}
.sw-managed{background:#f3efff;border-color:var(--lc)}
.sw-manager{background:#ddf4ff;border:2px solid var(--info)}
.sw-container{background:#fff1cc;border-color:#bf8700}
.sw-error{border:2px solid var(--err)}
.dot{display:inline-block;width:10px;height:10px;border-radius:50%;vertical-align:-1px;
margin:0 3px 0 6px}
.dia{display:inline-block;width:9px;height:9px;transform:rotate(45deg);margin:0 4px 0 6px}
.dot.st-active,.dia-done{background:var(--ok)}.dot.st-inactive{background:#d4a72c}
.dot.st-unconfigured{background:#afb8c1}.dot.st-finalized{background:#424a53}
.dia-blocked{background:var(--err)}
.picture{overflow-x:auto;margin:6px 0 10px}
svg.system{display:block;font-family:var(--sans)}
svg .ns rect{stroke:#b6c2cf;stroke-width:1}
svg .ns.d0>rect{fill:#f6f8fa}svg .ns.d1>rect{fill:#eaeef2}svg .ns.d2>rect{fill:#dfe5eb}
svg .ns.d3>rect{fill:#d3dbe3}
svg .ns.procs>rect{fill:#fff;stroke-dasharray:4 3}
svg .nsl{font:600 12px var(--sans);fill:#24292f}
svg .nsc{font:11px var(--sans);fill:var(--muted);text-anchor:end}
svg .node rect{fill:#fff;stroke:#8c959f;stroke-width:1}
svg .node.managed rect{fill:#f3efff;stroke:var(--lc)}
svg .node.manager rect{fill:#ddf4ff;stroke:var(--info);stroke-width:2}
svg .node.container>rect{fill:#fff1cc;stroke:#bf8700}
svg rect.ct{fill:#fffaeb;stroke:#d4a72c;stroke-width:1;stroke-dasharray:3 2}
svg .node.has-error>rect{stroke:var(--err);stroke-width:2.5}
svg .node.has-warning>rect{stroke:var(--warn);stroke-width:2}
svg .node:hover rect{filter:brightness(.95)}
svg .nl{font:11px var(--mono);fill:#1f2328}
svg .extra{font:10px var(--sans);fill:var(--muted);text-anchor:end}
svg rect.badge{stroke:none}
svg .node rect.b-error{fill:var(--err);stroke:none}
svg .node rect.b-warning{fill:#bf8700;stroke:none}
svg .node rect.b-info{fill:var(--info);stroke:none}
svg .bt{font:700 9px var(--sans);fill:#fff;text-anchor:middle}
svg .st-active{fill:var(--ok)}svg .st-inactive{fill:#d4a72c}svg .st-unconfigured{fill:#afb8c1}
svg .st-finalized{fill:#424a53}
svg .mgr-done{fill:var(--ok)}svg .mgr-blocked{fill:var(--err)}
details.flow-section>summary{margin:10px 0 4px}
ul.flow-legend{margin:4px 0}
.sw-cond{border-style:dashed}.sw-unknown{background:var(--soft);border:1px dotted #8c959f}
.pill{display:inline-block;width:22px;height:10px;border-radius:5px;vertical-align:0;
margin-right:5px;border:1px solid #54aeff;background:#ddf4ff}
.pill.p-services{border-color:#a475f9;background:#fbefff}
.pill.p-actions{border-color:#fb8f44;background:#fff1e5}
.pill.p-ref{background:#fff}
.pill.p-missing{border:2px solid var(--err);background:#fff}
.pill.p-unread{border:1px dashed #bf8700;background:#fff}
.ln{display:inline-block;width:24px;border-top:1.5px solid #8c959f;vertical-align:3px;
margin-right:5px}
.ln.ln-services{border-top:1.5px dashed #a475f9}.ln.ln-actions{border-top:2px dotted #fb8f44}
.flow{display:flex;flex-wrap:wrap;align-items:center;gap:4px 10px;margin:4px 0}
.flow>.flow-tools{order:0}.flow>.tf-toggle{order:1;margin:0}.flow>.tf-label{order:2;font-size:12px}
.flow>.picture{order:3;flex-basis:100%;max-height:92vh;overflow:auto;border:1px solid var(--line);
border-radius:6px}
.flow-tools{display:flex;align-items:center;gap:12px;font-size:12px}
.flow-filter{font:12px var(--mono);padding:2px 6px;width:340px;border:1px solid var(--line);
border-radius:4px}
.flow-status{color:var(--muted)}
svg.flow-svg{display:block;font-family:var(--sans)}
svg .fc>rect{fill:#f6f8fa;stroke:#b6c2cf;stroke-width:1}
svg .fnode rect{fill:#fff;stroke:#6e7781;stroke-width:1}
svg .fnode.cond rect{stroke-dasharray:4 2}
svg .fnode.unknown rect{fill:#f6f8fa;stroke:#8c959f;stroke-dasharray:1 2}
svg .fnode.unknown .nl{fill:var(--muted)}
svg .tag{font:700 10px var(--sans);fill:var(--lc);text-anchor:middle}
svg .fnode.unknown .tag{fill:var(--muted)}
svg .ftopic rect{fill:#ddf4ff;stroke:#54aeff;stroke-width:1}
svg .ftopic.s-services rect{fill:#fbefff;stroke:#a475f9}
svg .ftopic.s-actions rect{fill:#fff1e5;stroke:#fb8f44}
svg .ftopic.tf rect{fill:#eaeef2;stroke:#8c959f}
svg .ftopic.m-publisher rect,svg .ftopic.m-server rect{fill:#fff;stroke:var(--err);
stroke-width:2}
svg .ftopic.m-subscriber rect{fill:#fff;stroke:#bf8700;stroke-dasharray:3 2}
svg .tl{font:10px var(--mono);fill:#1f2328}
svg .fedge .el{fill:none;stroke:#8c959f;stroke-width:1}
svg .fedge .ah{fill:#8c959f}
svg .fedge.e-services .el{stroke:#a475f9;stroke-dasharray:4 3}
svg .fedge.e-services .ah{fill:#a475f9}
svg .fedge.e-actions .el{stroke:#fb8f44;stroke-dasharray:1 2;stroke-width:1.6}
svg .fedge.e-actions .ah{fill:#fb8f44}
svg .ftopic.ref rect{fill:#fff}
svg .fnode:hover rect,svg .ftopic:hover rect{filter:brightness(.93)}
.tf-toggle:not(:checked)~.picture .fedge.e-tf{display:none}
svg.focus .fnode:not(.on),svg.focus .ftopic:not(.on){opacity:.12}
svg.focus .fedge:not(.on){display:none}
.flow .picture svg.focus .fedge.on{display:inline}
svg.focus .fedge.on .el{stroke-width:1.8}
details{margin:6px 0}
summary{cursor:pointer;font-weight:600}
ul.plain{list-style:none;margin:0;padding:0}
table.nodes{table-layout:fixed}
table.nodes td{overflow-wrap:anywhere}
table.nodes th:nth-child(1){width:19%}table.nodes th:nth-child(2){width:7%}
table.nodes th:nth-child(3){width:14%}table.nodes th:nth-child(4){width:12%}
table.nodes th:nth-child(5){width:14%}table.nodes th:nth-child(6){width:23%}
table.nodes th:nth-child(7){width:11%}
.chip{display:inline-block;font-size:11px;border-radius:8px;padding:0 6px;margin:1px;
background:var(--soft);border:1px solid var(--line)}
.chip.st-active{background:#dafbe1;border-color:#4ac26b}
.chip.st-inactive{background:#fff8c5;border-color:#d4a72c}
.ok{color:var(--ok);font-weight:600}.bad{color:var(--err);font-weight:600}
tr:target{background:#ddf4ff}
ul.tree,ul.tree ul{list-style:none;padding-left:18px;margin:2px 0}
ul.tree li{border-left:1px solid var(--line);padding-left:8px;margin:2px 0}
.status{font-size:11px;border-radius:8px;padding:0 6px;border:1px solid var(--line)}
.status.bad{color:#fff;background:var(--err);border-color:var(--err)}
.status.off{color:var(--muted)}
.args code{font-size:11px;color:var(--muted);margin-right:8px}
.same{color:var(--muted);font-size:12px}
ul.plain li.from{margin-top:3px}
small.at{color:var(--muted)}
@media print{header.top{position:static}}
"""

# Optional: follow a link into a collapsed <details> (a node's row) by opening it; fill
# each reference to a block written earlier (html_shared) with a copy of it once it can
# be seen (its <details> open), so a page that says a thing once reads as if whole (a
# reference cell of a node's row takes the cells of the row it names but the first); the
# computation graph's filter box (shown only when this runs): the nodes whose name holds
# the text, the topics they use (with their copies in other namespaces), who publishes
# what they read and who reads what they publish (services: clients and servers), not
# through tf; the rest faded and the picture cropped to them.
SCRIPT = (
    "(function(){function show(){var id=decodeURIComponent(location.hash.slice(1));"
    "var t=id&&document.getElementById(id);if(!t)return;"
    "for(var e=t.parentElement;e;e=e.parentElement){if(e.tagName==='DETAILS')e.open=true;}"
    "fill(document);t.scrollIntoView();}"
    "function each(l,f){for(var i=0;i<l.length;i++)f(l[i]);}"
    "function seen(e){for(var p=e.parentElement;p;p=p.parentElement){"
    "if(p.tagName==='DETAILS'&&!p.open)return false;}return true;}"
    "function fill(root){each(root.querySelectorAll('.same[data-same]'),function(e){"
    "if(!e.parentNode||!seen(e))return;"
    "var t=document.getElementById(e.getAttribute('data-same'));if(!t)return;"
    "var up=e.parentNode,parts=t.tagName==='TR'?[].slice.call(t.cells,1):[t];"
    "each(parts,function(p){var c=p.cloneNode(true);c.removeAttribute('id');"
    "each(c.querySelectorAll('[id]'),function(x){x.removeAttribute('id');});"
    "up.insertBefore(c,e);});up.removeChild(e);fill(up);});}"
    "document.addEventListener('toggle',function(v){if(v.target.open)fill(v.target);},true);"
    "fill(document);window.addEventListener('hashchange',show);show();"
    "function filter(box){var svg=document.getElementById(box.getAttribute('data-flow'));"
    "if(!svg)return;var status=box.parentElement.querySelector('.flow-status');"
    "var parts=svg.querySelectorAll('[data-key]'),edges=svg.querySelectorAll('.fedge');"
    "var full=svg.getAttribute('data-box').split(' '),byKey={};box.hidden=false;"
    "each(parts,function(p){byKey[p.getAttribute('data-key')]=p;});"
    "var list=document.createElement('datalist'),names={},sorted=[];"
    "list.id=box.getAttribute('list');each(svg.querySelectorAll('.fnode'),function(p){"
    "var f=p.getAttribute('data-fqn');if(!names[f]){names[f]=1;sorted.push(f);}});"
    "sorted.sort();each(sorted,function(f){var o=document.createElement('option');"
    "o.value=f;list.appendChild(o);});box.parentElement.appendChild(list);"
    "function topic(k){return byKey[k]&&(byKey[k].getAttribute('data-topic')||k);}"
    "function size(b){svg.setAttribute('viewBox',b.join(' '));"
    "svg.setAttribute('width',b[2]);svg.setAttribute('height',b[3]);}"
    "function apply(){var q=box.value.trim();svg.classList.remove('focus');"
    "each(parts,function(p){p.classList.remove('on');});"
    "each(edges,function(p){p.classList.remove('on');});size(full);status.textContent='';"
    "if(!q)return;var hit={},n=0,up={},down={},keep={};"
    "each(svg.querySelectorAll('.fnode'),function(p){var k=p.getAttribute('data-key');"
    "if(p.getAttribute('data-fqn').indexOf(q)>=0){hit[k]=keep[k]=1;n++;}});"
    "if(!n){status.textContent='no node matches';return;}"
    "function ends(f){each(edges,function(e){f(e,e.getAttribute('data-a'),"
    "e.getAttribute('data-b'),e.classList.contains('e-tf'));});}"
    "ends(function(e,a,b,tf){if(hit[a]){keep[b]=1;if(!tf)down[topic(b)]=1;}"
    "if(hit[b]){keep[a]=1;if(!tf)up[topic(a)]=1;}});"
    "ends(function(e,a,b,tf){if(hit[a]||hit[b]||down[topic(a)]||up[topic(b)]){"
    "keep[a]=keep[b]=1;e.classList.add('on');}});"
    "var x0=1e9,y0=1e9,x1=-1e9,y1=-1e9,shown=0;"
    "for(var k in keep){var p=byKey[k];p.classList.add('on');shown++;"
    "var r=p.getBBox();x0=Math.min(x0,r.x);y0=Math.min(y0,r.y);"
    "x1=Math.max(x1,r.x+r.width);y1=Math.max(y1,r.y+r.height);}"
    "svg.classList.add('focus');var m=16;x0=Math.max(0,x0-m);y0=Math.max(0,y0-m);"
    "size([x0,y0,Math.ceil(x1+m-x0),Math.ceil(y1+m-y0)]);"
    "status.textContent=n+(n===1?' node matches':' nodes match')+', '+shown+"
    "' elements shown';}box.addEventListener('input',apply);apply();}"
    "each(document.querySelectorAll('.flow-filter'),filter);})();"
)

# What the page may load and run: its own style and the script above, nothing else. Should
# a launch file's text ever get through unescaped, the browser still refuses to run it.
CONTENT_SECURITY_POLICY = (
    "default-src 'none'; style-src 'unsafe-inline'; img-src data:; "
    "script-src 'sha256-"
    + base64.b64encode(hashlib.sha256(SCRIPT.encode("utf-8")).digest()).decode("ascii")
    + "'"
)
