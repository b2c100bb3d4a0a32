#!/usr/bin/env python3
# Lists the unfinished messages of a .ts file, and fills them from a translator's JSON lines,
# editing the text in place so the file stays byte-for-byte as lupdate writes it.
#   ts_fill.py list camwb_cs.ts > todo.jsonl   one {"context","source","numerus"} per line
#   ts_fill.py fill camwb_cs.ts done.jsonl     each line adds "translation": a string, or a
#                                              list of the 3 Czech plural forms when numerus
import html
import json
import re
import sys

MESSAGE = re.compile(
    r'(<message(?P<numerus> numerus="yes")?>\s*<source>(?P<source>(?:(?!</source>).)*)</source>\s*'
    r'(?:<comment>.*?</comment>\s*)?)<translation type="unfinished">.*?</translation>', re.S)
CONTEXT = re.compile(r'<context>\s*<name>(.*?)</name>(.*?)</context>', re.S)


def escape(text):
    # The entities lupdate writes.
    return (text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')
            .replace('"', '&quot;').replace("'", '&apos;'))


def unfinished(ts):
    for ctx in CONTEXT.finditer(ts):
        for m in MESSAGE.finditer(ctx.group(2)):
            yield html.unescape(ctx.group(1)), html.unescape(m.group('source')), bool(m.group('numerus'))


def fill(ts, translations):
    def context(ctx):
        name = html.unescape(ctx.group(1))

        def message(m):
            key = (name, html.unescape(m.group('source')))
            if key not in translations:
                return m.group(0)
            text = translations.pop(key)
            if m.group('numerus'):
                forms = ''.join('\n            <numerusform>%s</numerusform>' % escape(f) for f in text)
                return m.group(1) + '<translation>' + forms + '\n        </translation>'
            return m.group(1) + '<translation>' + escape(text) + '</translation>'
        return ctx.group(0)[:ctx.start(2) - ctx.start(0)] + MESSAGE.sub(message, ctx.group(2)) + '</context>'
    return CONTEXT.sub(context, ts)


def main():
    mode, path = sys.argv[1], sys.argv[2]
    ts = open(path, encoding='utf-8').read()
    if mode == 'list':
        for name, source, numerus in unfinished(ts):
            print(json.dumps({'context': name, 'source': source, 'numerus': numerus}, ensure_ascii=False))
        return 0
    rows = [json.loads(line) for line in open(sys.argv[3], encoding='utf-8') if line.strip()]
    translations = {(r['context'], r['source']): r['translation'] for r in rows}
    ts = fill(ts, translations)
    open(path, 'w', encoding='utf-8').write(ts)
    for name, source in translations:
        print('not an unfinished message: %s: %r' % (name, source), file=sys.stderr)
    return 1 if translations else 0


if __name__ == '__main__':
    sys.exit(main())
