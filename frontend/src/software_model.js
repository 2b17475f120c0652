// Edits of a MODEL (src/web/API.md), as pure functions returning a new MODEL. The server's
// printer then checks the result and gives back the canonical string.
import { completeParameters, findModule, getCatalogue } from './catalogue.js';

const clone = (x) => structuredClone(x);

export function moduleInstance(kind, id, given) {
  return { id, parameters: completeParameters(kind, id, given) };
}

/// The first condition of the flavour of a behaviour (a sensible default for a new transition).
export function defaultCondition(behaviourId) {
  const b = findModule('behaviour', behaviourId);
  const list = getCatalogue().conditions;
  return (b && list.find((c) => c.flavour === b.flavour)) || list[0];
}

export function newFsm(behaviourId = 10) {
  return { architecture: 'fsm', states: [{ behaviour: moduleInstance('behaviour', behaviourId), transitions: [] }] };
}

export function addState(model, behaviourId) {
  const m = clone(model);
  m.states.push({ behaviour: moduleInstance('behaviour', behaviourId), transitions: [] });
  return m;
}

export function removeState(model, index) {
  const m = clone(model);
  m.states.splice(index, 1);
  for (const s of m.states) {
    s.transitions = s.transitions.filter((t) => t.target !== index);
    for (const t of s.transitions) if (t.target > index) t.target -= 1;
  }
  return m;
}

/// Makes state `index` the initial one (state 0) by swapping it with state 0.
export function makeInitial(model, index) {
  if (index === 0) return model;
  const m = clone(model);
  const swap = (k) => (k === 0 ? index : k === index ? 0 : k);
  [m.states[0], m.states[index]] = [m.states[index], m.states[0]];
  for (const s of m.states) for (const t of s.transitions) t.target = swap(t.target);
  return m;
}

export function addTransition(model, from, to, conditionId) {
  const m = clone(model);
  m.states[from].transitions.push({ target: to, condition: moduleInstance('condition', conditionId) });
  return m;
}

export function removeTransition(model, state, transition) {
  const m = clone(model);
  m.states[state].transitions.splice(transition, 1);
  return m;
}

export function setStateBehaviour(model, index, behaviourId) {
  const m = clone(model);
  const old = m.states[index].behaviour.parameters;
  m.states[index].behaviour = moduleInstance('behaviour', behaviourId, old);
  return m;
}

export function setTransitionCondition(model, state, transition, conditionId) {
  const m = clone(model);
  const t = m.states[state].transitions[transition];
  t.condition = moduleInstance('condition', conditionId, t.condition.parameters);
  return m;
}

/// Sets a parameter of the module found by `locate(model)`; drops parameters made inactive.
export function setParameter(model, locate, kind, token, value) {
  const m = clone(model);
  const module = locate(m);
  module.parameters = completeParameters(kind, module.id, { ...module.parameters, [token]: value });
  return m;
}

// ---- behaviour trees ----

const firstOf = (kind, flavour) => {
  const c = getCatalogue();
  return (kind === 'behaviour' ? c.behaviours : c.conditions).find((m) => m.flavour === flavour);
};

/// Maple's shape: a sequence* root over selectors, each a condition then an action.
export function newMapleTree() {
  const cond = firstOf('condition', 'maple') || getCatalogue().conditions[0];
  const act = firstOf('behaviour', 'maple') || getCatalogue().behaviours[0];
  return {
    architecture: 'bt',
    nodes: [
      { type: 'sequence*', children: [1] },
      { type: 'selector', children: [2, 3] },
      { type: 'condition', module: moduleInstance('condition', cond.id) },
      { type: 'action', module: moduleInstance('behaviour', act.id), success: 0 },
    ],
  };
}

export function isComposite(node) { return node && node.type !== 'action' && node.type !== 'condition'; }

export function addBtChild(model, parent, node) {
  const m = clone(model);
  const index = m.nodes.length;
  m.nodes.push(node);
  m.nodes[parent].children.push(index);
  return m;
}

export function btNode(kind, id) {
  return kind === 'behaviour'
    ? { type: 'action', module: moduleInstance('behaviour', id), success: 0 }
    : { type: 'condition', module: moduleInstance('condition', id) };
}

/// Removes node `index` and its subtree (never the root); indices are renumbered.
export function removeBtNode(model, index) {
  if (index === 0) return model;
  const doomed = new Set();
  const mark = (i) => { doomed.add(i); for (const c of model.nodes[i].children || []) mark(c); };
  mark(index);
  const renumber = new Map();
  model.nodes.forEach((_, i) => { if (!doomed.has(i)) renumber.set(i, renumber.size); });
  const nodes = [];
  model.nodes.forEach((n, i) => {
    if (doomed.has(i)) return;
    const copy = clone(n);
    if (copy.children) copy.children = copy.children.filter((c) => !doomed.has(c)).map((c) => renumber.get(c));
    nodes.push(copy);
  });
  return { ...clone(model), nodes };
}

export function setBtType(model, index, type) {
  const m = clone(model);
  m.nodes[index].type = type;
  return m;
}

export function setBtModule(model, index, id) {
  const m = clone(model);
  const n = m.nodes[index];
  n.module = moduleInstance(n.type === 'action' ? 'behaviour' : 'condition', id, n.module.parameters);
  return m;
}

export function setBtSuccess(model, index, value) {
  const m = clone(model);
  m.nodes[index].success = value;
  return m;
}

/// Name of what state / node `index` runs, for the robot panel.
export function describeIndex(model, index) {
  if (!model) return String(index);
  if (model.architecture === 'fsm') {
    const s = model.states[index];
    if (!s) return `state ${index}`;
    const b = findModule('behaviour', s.behaviour.id);
    return `state ${index}: ${String(s.behaviour.id).padStart(2, '0')} ${b ? b.name : '?'}`;
  }
  if (model.architecture === 'bt') {
    const n = model.nodes[index];
    if (!n) return `node ${index}`;
    if (n.module) {
      const spec = findModule(n.type === 'action' ? 'behaviour' : 'condition', n.module.id);
      return `node ${index} (${n.type}): ${String(n.module.id).padStart(2, '0')} ${spec ? spec.name : '?'}`;
    }
    return `node ${index} (${n.type})`;
  }
  return `${index}`;
}

/// Each tree node's name in the configuration string: the root is `root`, child c of the root
/// `n{c}`, child d of `n{c}` `n{c}{d}` (bt_config.cpp's numbering), by model index.
export function btNodeNames(model) {
  const names = [];
  if (!model || model.architecture !== 'bt' || !model.nodes.length) return names;
  names[0] = 'root';
  const walk = (index, path) => {
    (model.nodes[index].children || []).forEach((child, c) => {
      const name = `${path}${c}`;
      if (names[child] === undefined) { names[child] = `n${name}`; walk(child, name); }
    });
  };
  walk(0, '');
  return names;
}

/// The flavours whose modules a MODEL uses, in catalogue order.
export function flavoursUsed(model, catalogue) {
  if (!model || !catalogue) return [];
  const ids = [];
  if (model.architecture === 'fsm') {
    for (const s of model.states) {
      ids.push(['behaviour', s.behaviour.id]);
      for (const t of s.transitions) ids.push(['condition', t.condition.id]);
    }
  } else if (model.architecture === 'bt') {
    for (const n of model.nodes) if (n.module) ids.push([n.type === 'action' ? 'behaviour' : 'condition', n.module.id]);
  }
  const used = new Set(ids.map(([kind, id]) => (findModule(kind, id) || {}).flavour).filter(Boolean));
  return catalogue.flavours.map((f) => f.name).filter((name) => used.has(name));
}
