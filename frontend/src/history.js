// Undo/redo over snapshots of the editor ({model, text}).
export class History {
  constructor(limit = 200) { this.limit = limit; this.past = []; this.future = []; this.present = null; }

  push(snapshot) {
    if (this.present && this.present.text === snapshot.text) { this.present = snapshot; return; }
    if (this.present) this.past.push(this.present);
    if (this.past.length > this.limit) this.past.shift();
    this.present = snapshot;
    this.future = [];
  }
  canUndo() { return this.past.length > 0; }
  canRedo() { return this.future.length > 0; }
  undo() {
    if (!this.canUndo()) return null;
    this.future.push(this.present);
    this.present = this.past.pop();
    return this.present;
  }
  redo() {
    if (!this.canRedo()) return null;
    this.past.push(this.present);
    this.present = this.future.pop();
    return this.present;
  }
}
