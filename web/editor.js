// editor.js: the effect editor, CodeMirror 6 (bundled by esbuild into editor.bundle.js at build
// time, so the page needs no network and no module loader). HLSL reads close enough to C++ for
// its highlighter. Exposes window.HfxEditor to app.js.
import {EditorView, basicSetup} from "codemirror";
import {cpp} from "@codemirror/lang-cpp";
import {setDiagnostics, lintGutter} from "@codemirror/lint";

function offsetOf(doc, line, col) {
  const l = doc.line(Math.min(Math.max(line, 1), doc.lines));
  return Math.min(l.from + Math.max(col - 1, 0), l.to);
}

window.HfxEditor = {
  // parent: an element; onChange(text) after every edit.
  create(parent, onChange) {
    const view = new EditorView({
      parent,
      extensions: [basicSetup, cpp(), lintGutter(),
        // Files dropped on the editor open as the effect (app.js's drop handler, which the event
        // bubbles up to) instead of CodeMirror pasting their text into the current file.
        EditorView.domEventHandlers({drop: (e) => !!(e.dataTransfer && e.dataTransfer.files.length)}),
        EditorView.updateListener.of((u) => { if (u.docChanged) onChange(u.state.doc.toString()); })],
    });
    return {
      view,
      getText: () => view.state.doc.toString(),
      setText(text) {
        view.dispatch({changes: {from: 0, to: view.state.doc.length, insert: text}});
      },
      // diags: [{line, col, severity, message}] of this file; each marks the word at its column.
      mark(diags) {
        const doc = view.state.doc;
        const list = diags.map((d) => {
          const from = offsetOf(doc, d.line, d.col);
          const lineEnd = doc.lineAt(from).to;
          const word = /^[\w.]+/.exec(doc.sliceString(from, lineEnd));
          const to = Math.min(from + (word ? word[0].length : 1), lineEnd);
          return {from, to: Math.max(to, from), severity: d.severity === "note" ? "info" : d.severity, message: d.message};
        });
        view.dispatch(setDiagnostics(view.state, list));
      },
      goto(line, col) {
        const at = offsetOf(view.state.doc, line, col);
        view.dispatch({selection: {anchor: at}, scrollIntoView: true});
        view.focus();
      },
    };
  },
};
