// Undo and redo over snapshots of a value (the editor's rows): small, so whole copies are simplest
// and an undo can never disagree with what was shown.
export class UndoHistory {
  constructor(initial) {
    this.states = [structuredClone(initial)];
    this.at = 0;
  }

  get current() { return structuredClone(this.states[this.at]); }
  get canUndo() { return this.at > 0; }
  get canRedo() { return this.at < this.states.length - 1; }

  // Records a new state (dropping what could be redone); a state equal to the current one is no edit.
  push(state) {
    if (JSON.stringify(state) === JSON.stringify(this.states[this.at])) return false;
    this.states.splice(this.at + 1, Infinity, structuredClone(state));
    this.at++;
    return true;
  }

  undo() { if (this.canUndo) this.at--; return this.current; }
  redo() { if (this.canRedo) this.at++; return this.current; }
}
