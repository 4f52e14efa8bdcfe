// The page's editor: CodeMirror 6 with RobotBASIC highlighting, rb's diagnostics in the gutter
// and under the text, and the line of a runtime error marked. Bundled by scripts/web.sh
// (esbuild) into editor.js, which sets window.RbEditor; web/app.js falls back to its text area
// without it.
import {EditorState, StateEffect, StateField} from '@codemirror/state';
import {EditorView, Decoration, keymap, lineNumbers, highlightActiveLine, highlightActiveLineGutter,
  drawSelection} from '@codemirror/view';
import {defaultKeymap, history, historyKeymap, indentWithTab} from '@codemirror/commands';
import {StreamLanguage, syntaxHighlighting, defaultHighlightStyle, bracketMatching} from '@codemirror/language';
import {setDiagnostics, lintGutter} from '@codemirror/lint';
import {helpExtensions, setUpReference} from './help.mjs';

const KEYWORDS = new Set(('if then else elseif endif for to step next while wend repeat until do loop ' +
  'gosub goto return sub call end print input and or not mod xor break continue case select ' +
  'endsub onerror data dim byref declare include true false').split(' '));

const robotBasic = StreamLanguage.define({
  name: 'robotbasic',
  startState: () => ({lineStart: true}),
  token(stream, state) {
    if (stream.sol()) state.lineStart = true;
    if (stream.eatSpace()) return null;
    const first = state.lineStart;
    state.lineStart = false;
    if (stream.match('//') || stream.match("'")) { stream.skipToEnd(); return 'comment'; }
    if (stream.match(/^"[^"]*"?/)) return 'string';
    if (stream.match(/^\d+(\.\d*)?(e[+-]?\d+)?/i) || stream.match(/^\.\d+/)) return 'number';
    const w = stream.match(/^[A-Za-z_][A-Za-z_0-9]*/);
    if (w) {
      const word = w[0].toLowerCase();
      if (first && stream.peek() === ':') { stream.next(); return 'labelName'; }
      if (first && word === 'rem') { stream.skipToEnd(); return 'comment'; }
      if (KEYWORDS.has(word)) return 'keyword';
      // (A tag's modifier follows it: 'variableName.function' is tags.function(tags.variableName).)
      if (/^r[A-Z]/.test(w[0])) return 'variableName.function';
      return 'variableName';
    }
    stream.next();
    return /[-+*\/=<>&|^%]/.test(stream.current()) ? 'operator' : null;
  },
  languageData: {commentTokens: {line: '//'}},
});

// The line of the last runtime error ({line, step: false}), or the statement a stepped run
// stops before ({line, step: true}).
const setErrorLine = StateEffect.define();
const errorLineMark = Decoration.line({class: 'rb-errline'});
const stepLineMark = Decoration.line({class: 'rb-stepline'});
const errorLine = StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    deco = deco.map(tr.changes);
    for (const e of tr.effects) {
      if (!e.is(setErrorLine)) continue;
      const {line, step} = e.value;
      deco = line > 0 && line <= tr.state.doc.lines
        ? Decoration.set([(step ? stepLineMark : errorLineMark).range(tr.state.doc.line(line).from)])
        : Decoration.none;
    }
    if (tr.docChanged) deco = Decoration.none;
    return deco;
  },
  provide: (f) => EditorView.decorations.from(f),
});

setUpReference();  // the command reference (web/help.mjs)

window.RbEditor = {
  create(parent, {doc, onChange, onRun}) {
    const extensions = [
      lineNumbers(), highlightActiveLineGutter(), history(), drawSelection(), highlightActiveLine(),
      bracketMatching(), robotBasic, syntaxHighlighting(defaultHighlightStyle), lintGutter(), errorLine,
      ...helpExtensions(),
      keymap.of([{key: 'Mod-Enter', run: () => { onRun(); return true; }}, indentWithTab,
                 ...defaultKeymap, ...historyKeymap]),
      EditorView.updateListener.of((u) => { if (u.docChanged) onChange(); }),
      // Its name for screen readers; the page's keys menu says how to leave it (Esc, Tab).
      EditorView.contentAttributes.of({'aria-label': 'Program (RobotBASIC)'}),
    ];
    const view = new EditorView({parent, state: EditorState.create({doc, extensions})});
    // rb's columns count the line's UTF-8 bytes (1-based); the editor's positions count UTF-16
    // code units: a line with "é" or "ü" before the column puts them apart.
    const pos = (line, col) => {
      const l = view.state.doc.line(Math.min(Math.max(1, line), view.state.doc.lines));
      let bytes = Math.max(0, (col || 1) - 1), i = 0;
      const text = l.text;
      while (bytes > 0 && i < text.length) {
        const c = text.codePointAt(i);
        bytes -= c < 0x80 ? 1 : c < 0x800 ? 2 : c < 0x10000 ? 3 : 4;
        i += c >= 0x10000 ? 2 : 1;
      }
      return Math.min(l.to, l.from + i);
    };
    return {
      view,
      get value() { return view.state.doc.toString(); },
      set value(text) { view.dispatch({changes: {from: 0, to: view.state.doc.length, insert: text}}); },
      // Another program: a fresh state, with no undo back into the text before.
      reset(text) { view.setState(EditorState.create({doc: text, extensions})); },
      setDiagnostics(list) {
        const diags = list.filter((d) => d.line > 0 && d.severity !== 'note').map((d) => {
          const from = pos(d.line, d.col);
          let to = d.endLine ? pos(d.endLine, d.endCol) + 1 : from + 1;
          to = Math.min(Math.max(to, from), view.state.doc.length);
          return {from, to, severity: d.severity, message: d.message + (d.code ? ` [${d.code}]` : '')};
        });
        view.dispatch(setDiagnostics(view.state, diags));
      },
      setErrorLine(line) { view.dispatch({effects: setErrorLine.of({line: line || 0, step: false})}); },
      setStepLine(line) {
        view.dispatch({effects: setErrorLine.of({line: line || 0, step: true})});
        if (line > 0 && line <= view.state.doc.lines) {
          view.dispatch({effects: EditorView.scrollIntoView(view.state.doc.line(line).from, {y: 'nearest'})});
        }
      },
      goToLine(line) {
        const l = view.state.doc.line(Math.min(Math.max(1, line), view.state.doc.lines));
        view.dispatch({selection: {anchor: l.from, head: l.to}, scrollIntoView: true});
        view.focus();
      },
      focus() { view.focus(); },
    };
  },
};
