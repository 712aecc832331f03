#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Opens a report folder's index.html in headless Chromium at 800, 1280 and 1920 px and checks what a reader would
see: no element (with every <details> opened) wider than the viewport, every image loaded, the headline's claim
counts equal to results.json's (FAIL: what fails the run, as the terminal counts it; refuted study statements
apart), the answer sentences inside the first 900 px at 800 and 1280 px, and every link resolving inside the folder (no network, no absolute paths; a link
marked data-made-after names a file ci/main.sh writes after the report, e.g. Figure 3, and must stay inside it).

usage: report_browser.py CHROMIUM REPORT_DIR WORKDIR
"""
import html
import json
import os
import re
import subprocess
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlparse

PROBE = """<script>
window.addEventListener('load', () => {
  document.querySelectorAll('details').forEach(d => d.open = true);
  const vw = document.documentElement.clientWidth, wide = [];
  for (const el of document.querySelectorAll('body *')) {
    // A table in a scrolling box (.wide) may be wider than the page; the box itself may not.
    const box = el.closest('.wide');
    if (box && box !== el) continue;
    const r = el.getBoundingClientRect();
    if (r.width > 0 && (r.right > vw + 0.5 || r.left < -0.5))
      wide.push(el.tagName + (el.id ? '#' + el.id : '') + ' right=' + Math.round(r.right));
  }
  const images = [...document.images].map(i => ({src: i.getAttribute('src'), loaded: i.complete && i.naturalWidth > 0,
                                                alt: i.getAttribute('alt') || ''}));
  const text = id => (document.getElementById(id) || {}).textContent;
  // The answers: every sentence's bottom edge, in page pixels from the top.
  const answers = [...document.querySelectorAll('#answers .answer')].map(
      a => ({bottom: Math.round(a.getBoundingClientRect().bottom + window.scrollY), text: a.textContent.slice(0, 60)}));
  const out = {viewport: vw, scrollWidth: document.documentElement.scrollWidth, wide, images, answers,
               counts: {total: text('claims-total'), pass: text('claims-pass'), fail: text('claims-fail'),
                        refuted: text('claims-refuted'), reported: text('claims-reported'),
                        not_separated: text('claims-not-separated')}};
  const pre = document.createElement('pre');
  pre.id = 'browser-probe';
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
});
</script>"""


FIRST_SCREEN = 900  # px: what a reader sees before scrolling


class Links(HTMLParser):
    def __init__(self):
        super().__init__()
        self.links, self.ids = [], set()

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if 'id' in a:
            self.ids.add(a['id'])
        for key in ('href', 'src'):
            if key in a and a[key] is not None:
                self.links.append((tag, a[key], 'data-made-after' in a))


def main():
    chromium, report, work = sys.argv[1:4]
    failures = []
    index = os.path.join(report, 'index.html')
    page = open(index, encoding='utf-8').read()

    # Links: relative, inside the folder, existing; anchors name an id of the page.
    parser = Links()
    parser.feed(page)
    for tag, link, made_after in parser.links:
        u = urlparse(link)
        if u.scheme or u.netloc or link.startswith('/'):
            failures.append(f'{tag} link leaves the folder: {link}')
        elif link.startswith('#'):
            if link[1:] not in parser.ids:
                failures.append(f'anchor {link} names no element')
        elif '..' in u.path.split('/'):
            failures.append(f'{tag} link leaves the folder: {link}')
        elif not made_after and not os.path.exists(os.path.join(report, unquote(u.path))):
            failures.append(f'{tag} link does not resolve: {link}')

    # The browser: a probe script in a copy of the page beside the original, so relative links still resolve.
    probe_page = os.path.join(report, 'index.browser-probe.html')
    open(probe_page, 'w', encoding='utf-8').write(page.replace('</body>', PROBE + '</body>'))
    probes = []
    for width in (800, 1280, 1920):
        cmd = [chromium, '--headless', '--no-sandbox', '--disable-gpu', '--hide-scrollbars', '--no-first-run',
               '--user-data-dir=' + os.path.join(work, 'chromium-profile'), f'--window-size={width},900',
               '--virtual-time-budget=10000', '--dump-dom', 'file://' + os.path.abspath(probe_page)]
        dom = subprocess.run(cmd, capture_output=True, text=True, timeout=120).stdout
        m = re.search(r'<pre id="browser-probe">(.*?)</pre>', dom, re.S)
        if not m:
            os.remove(probe_page)
            print(f'FAILED: the probe did not run at {width} px (no result in the DOM)')
            return 1
        probe = json.loads(html.unescape(m.group(1)))
        probes.append(probe)
        print(f"viewport {probe['viewport']} px, document {probe['scrollWidth']} px wide, {len(probe['images'])} images")
        if probe['viewport'] != width:
            failures.append(f"viewport is {probe['viewport']} px, not {width}")
        if probe['scrollWidth'] > probe['viewport']:
            failures.append(f"horizontal overflow at {width} px: document {probe['scrollWidth']} px")
        for w in probe['wide']:
            failures.append(f'wider than the {width} px viewport: ' + w)
        # The first screen answers the study: every sentence ends within the first 900 px (<details> are opened by
        # the probe after layout of the first screen, which holds none).
        if not probe['answers']:
            failures.append(f'no answer sentences (#answers .answer) at {width} px')
        elif width in (800, 1280):
            last = max(a['bottom'] for a in probe['answers'])
            print(f"  {len(probe['answers'])} answer sentences, the last ending at {last} px")
            for a in probe['answers']:
                if a['bottom'] > FIRST_SCREEN:
                    failures.append(f"answer below the first {FIRST_SCREEN} px at {width} px ({a['bottom']} px): "
                                    f"{a['text']}")
    os.remove(probe_page)
    probe = probes[1]
    for i in probe['images']:
        if not i['loaded']:
            failures.append(f"image not loaded: {i['src']}")
        if not i['alt'].strip():
            failures.append(f"image without alt text: {i['src']}")

    # The headline against results.json.
    results = json.load(open(os.path.join(report, 'results.json'), encoding='utf-8'))
    checks = results['checks']
    kept = [c for c in checks if not c['fails_run']]
    expected = {'total': len(checks), 'pass': sum(c['status'] == 'PASS' for c in kept),
                'fail': sum(bool(c['fails_run']) for c in checks),
                'refuted': sum(c['status'] == 'FAIL' and bool(c['study']) for c in kept),
                'reported': sum(c['status'] == 'FAIL' and not c['study'] for c in kept),
                'not_separated': sum(c['status'] == 'NOT SEPARATED' for c in kept)}
    shown = {k: int(v) if v is not None else None for k, v in probe['counts'].items()}
    print(f'headline {shown}, results.json {expected}')
    if shown != expected:
        failures.append(f'headline counts {shown} differ from results.json {expected}')

    for f in failures:
        print('FAILED: ' + f)
    if not failures:
        print('report in the browser: ok')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
