// The page's help, from rb's built-in table as the core gives it (rb.builtins(): api.cpp's
// rb_builtins, the rows the language server reads): completion and hover in the editor, with the
// language server's text (lsp/server.cpp: a completion's detail is the usage and its
// documentation the one-line help; a hover is the usage, the help, and the group and kind), and
// the command reference, a dialog that searches the table (name, usage, what it does, evidence).
// Bundled into editor.js with web/editor.mjs; nothing here lists a built-in.
import {autocompletion} from '@codemirror/autocomplete';
import {hoverTooltip} from '@codemirror/view';

const table = () => (window.rb ? window.rb.builtins() : Promise.resolve([]));

// The tier as docs/builtins.md words it.
export const TIER = {confirmed: 'a RobotBASIC source shows it', recalled: 'recalled from RobotBASIC\'s manual',
  own: 'rb\'s own'};
function evidence(b) {
  if (b.tier === 'confirmed') return b.source;
  if (b.tier === 'recalled') return b.recalled + (b.instead ? `; the sources show instead: ${b.instead}` : '');
  return b.reason + (b.instead ? `; RobotBASIC has instead: ${b.instead}` : '');
}
const helpLine = (b) => b.help + (b.kind === 'constant' ? ` (= ${b.value})` : '');

// Where a word stands: the first word of a statement takes commands, anywhere else functions
// and constants (as the language server offers them).
function atStatement(before) {
  return /^\s*$/.test(before) || /^\s*[A-Za-z_]\w*:\s*$/.test(before) || /\b(then|else)\s+$/i.test(before);
}
function inStringOrComment(before) {
  let quote = false;
  for (let i = 0; i < before.length; i++) {
    const c = before[i];
    if (c === '"') quote = !quote;
    else if (!quote && (c === '\'' || (c === '/' && before[i + 1] === '/'))) return true;
  }
  return quote || /^\s*rem\b/i.test(before);
}

async function complete(context) {
  const word = context.matchBefore(/[A-Za-z_][A-Za-z_0-9]*/);
  if (!word && !context.explicit) return null;
  const from = word ? word.from : context.pos;
  const line = context.state.doc.lineAt(from);
  const before = line.text.slice(0, from - line.from);
  if (inStringOrComment(before)) return null;
  const statement = atStatement(before);
  const rows = await table();
  const options = rows.filter((b) => (b.kind === 'command') === statement).map((b) => ({
    label: b.name,
    type: b.kind === 'constant' ? 'constant' : 'function',
    detail: b.usage,
    info: helpLine(b),
  }));
  return {from, options, validFor: /^[A-Za-z_0-9]*$/};
}

function hoverDom(rows) {
  const dom = document.createElement('div');
  dom.className = 'rb-hover';
  rows.forEach((b, i) => {
    if (i) dom.appendChild(document.createElement('hr'));
    const code = document.createElement('code');
    code.textContent = b.usage;
    const help = document.createElement('p');
    help.textContent = helpLine(b);
    const kind = document.createElement('p');
    kind.className = 'kind';
    kind.textContent = `${b.group} ${b.kind} · ${TIER[b.tier]}`;
    dom.append(code, help, kind);
  });
  return dom;
}

const hover = hoverTooltip(async (view, pos) => {
  const line = view.state.doc.lineAt(pos);
  const at = pos - line.from;
  let start = at, end = at;
  while (start > 0 && /\w/.test(line.text[start - 1])) start--;
  while (end < line.text.length && /\w/.test(line.text[end])) end++;
  if (start === end || !/^[A-Za-z_]/.test(line.text.slice(start, end))) return null;
  if (inStringOrComment(line.text.slice(0, start))) return null;
  const word = line.text.slice(start, end).toLowerCase();
  const rows = (await table()).filter((b) => b.name.toLowerCase() === word);
  if (!rows.length) return null;
  return {pos: line.from + start, end: line.from + end, above: true, create: () => ({dom: hoverDom(rows)})};
});

// The editor's help: completion (as you type, or Ctrl+Space) and hover.
export function helpExtensions() {
  return [autocompletion({override: [complete], icons: false}), hover];
}

// ---- the command reference: a dialog with a search box and the table's rows that match.
function row(b) {
  const li = document.createElement('li');
  const name = document.createElement('code');
  name.className = 'usage';
  name.textContent = b.usage;
  const what = document.createElement('span');
  what.className = 'what';
  what.textContent = helpLine(b);
  const meta = document.createElement('span');
  meta.className = 'meta';
  meta.textContent = `${b.group} ${b.kind}; ${TIER[b.tier]}` + (evidence(b) ? `: ${evidence(b)}` : '');
  li.append(name, ' ', what, meta);
  return li;
}
function matches(b, words) {
  const text = `${b.name} ${b.usage} ${b.help} ${b.group} ${b.kind}`.toLowerCase();
  return words.every((w) => text.includes(w));
}
export function setUpReference() {
  const dialog = document.getElementById('reference');
  const search = document.getElementById('referenceSearch');
  const list = document.getElementById('referenceList');
  const count = document.getElementById('referenceCount');
  const open = document.getElementById('help');
  if (!dialog || !search || !list || !open) return;
  const show = async () => {
    const rows = await table();
    const words = search.value.toLowerCase().split(/\s+/).filter(Boolean);
    const hits = rows.filter((b) => matches(b, words));
    list.textContent = '';
    for (const b of hits.slice(0, 200)) list.appendChild(row(b));
    count.textContent = hits.length === rows.length ? `${rows.length} built-ins` : `${hits.length} of ${rows.length} built-ins`;
  };
  search.addEventListener('input', show);
  open.addEventListener('click', () => {
    dialog.showModal();
    search.focus();
    search.select();
    show();
  });
  window.rbHelp = {show};
}
