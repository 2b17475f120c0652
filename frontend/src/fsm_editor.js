// FSM editing: states from the palette's behaviours, transitions drawn by dragging
// (cytoscape-edgehandles) with the armed condition, the state / transition property panels.
import { getCatalogue, twoDigits } from './catalogue.js';
import { el, moduleSelect, parameterFields } from './properties.js';
import * as sm from './software_model.js';
import { showError } from './toast.js';

export function fsmEditor(ctx) {
  const { cy } = ctx;
  const limits = () => getCatalogue().limits;
  let armedCondition = null;

  const eh = cy.edgehandles({
    canConnect: (source, target) => ctx.mode() === 'fsm' && !source.same(target) && source.data('kind') === 'state' && target.data('kind') === 'state',
    edgeParams: () => ({ data: { kind: 'preview' } }),
    snap: true,
    hoverDelay: 100,
  });
  cy.on('ehcomplete', (event, source, target, added) => {
    added.remove();
    const model = ctx.model();
    const from = source.data('index');
    if (model.states[from].transitions.length >= limits().fsm_transitions) {
      showError(`a state has at most ${limits().fsm_transitions} transitions`);
      return;
    }
    const condition = armedCondition ?? sm.defaultCondition(model.states[from].behaviour.id).id;
    ctx.commit(sm.addTransition(model, from, target.data('index'), condition), { select: `t${from}_${model.states[from].transitions.length}` });
  });

  return {
    setDrawMode(on) { if (on) eh.enableDrawMode(); else eh.disableDrawMode(); },
    /// Programmatic transition (used by tests and keyboard users): from → to.
    addTransition(from, to) {
      const model = ctx.model();
      const condition = armedCondition ?? sm.defaultCondition(model.states[from].behaviour.id).id;
      ctx.commit(sm.addTransition(model, from, to, condition));
    },
    pick(kind, module) {
      const model = ctx.model();
      if (kind === 'behaviour') {
        if (model.states.length >= limits().fsm_states) { showError(`an FSM has at most ${limits().fsm_states} states`); return; }
        ctx.commit(sm.addState(model, module.id), { select: `s${model.states.length}` });
      } else {
        const sel = cy.$('edge:selected');
        if (sel.length) {
          ctx.commit(sm.setTransitionCondition(model, sel.data('state'), sel.data('transition'), module.id));
        } else {
          armedCondition = module.id;
          ctx.arm('condition', module.id);
        }
      }
    },
    remove(element) {
      const model = ctx.model();
      if (element.data('kind') === 'state') {
        if (model.states.length <= 1) { showError('an FSM keeps at least one state'); return; }
        ctx.commit(sm.removeState(model, element.data('index')));
      } else if (element.data('kind') === 'transition') {
        ctx.commit(sm.removeTransition(model, element.data('state'), element.data('transition')));
      }
    },
    properties(element, panel) {
      const model = ctx.model();
      if (element.data('kind') === 'state') {
        const i = element.data('index');
        const state = model.states[i];
        panel.append(
          el('div', { class: 'props-title', text: `State ${i}${i === 0 ? ' (initial)' : ''}` }),
          el('label', { text: 'Behaviour' }),
          moduleSelect('behaviour', state.behaviour.id, (id) => ctx.commit(sm.setStateBehaviour(model, i, id)), 'module-select'),
          parameterFields('behaviour', state.behaviour, (token, v) =>
            ctx.commit(sm.setParameter(model, (m) => m.states[i].behaviour, 'behaviour', token, v))),
          el('div', { class: 'row' },
            el('button', { testid: 'make-initial', text: 'Make initial', onclick: () => ctx.commit(sm.makeInitial(model, i), { select: 's0' }) }),
            el('button', { testid: 'delete-state', text: 'Delete state', onclick: () => this.remove(element) })),
          el('p', { class: 'muted small', text: `Transitions: ${state.transitions.length} / ${limits().fsm_transitions}. Drag from this state to another with “Draw transitions” on.` }));
      } else if (element.data('kind') === 'transition') {
        const i = element.data('state');
        const j = element.data('transition');
        const t = model.states[i].transitions[j];
        panel.append(
          el('div', { class: 'props-title', text: `Transition S${i} → S${t.target}` }),
          el('label', { text: 'Condition' }),
          moduleSelect('condition', t.condition.id, (id) => ctx.commit(sm.setTransitionCondition(model, i, j, id)), 'module-select'),
          parameterFields('condition', t.condition, (token, v) =>
            ctx.commit(sm.setParameter(model, (m) => m.states[i].transitions[j].condition, 'condition', token, v))),
          el('div', { class: 'row' },
            el('button', { testid: 'delete-transition', text: 'Delete transition', onclick: () => this.remove(element) })));
      }
    },
    hint() {
      const c = armedCondition !== null ? `${twoDigits(armedCondition)}` : 'the flavour\'s first';
      return `Click a behaviour to add a state; click a condition to choose the one new transitions get (now: ${c}).`;
    },
  };
}
