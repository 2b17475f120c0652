// The start-a-design form of the Designs tab: the same choices as `run-design` (--fsm / --bt,
// flavour flags, --method, a seed) plus the project's budget, with the thesis' presets and the
// least budget the chosen method accepts for the chosen space (GET /api/design-space, which
// also lists the methods).
import { api } from './api.js';
import { el } from './properties.js';

const $ = (id) => document.getElementById(id);

/// What each flavour brings to a design (README, "Modules of every flavour").
export const FLAVOUR_NOTES = {
  chocolate: 'six behaviours (exploration, stop, phototaxis, anti-phototaxis, attraction, repulsion); floor-colour, neighbour and probability conditions',
  tuttifrutti: 'RGB LEDs: every behaviour shows a colour; go to / away from a colour; colour-detection conditions (FSMs only in its code base)',
  coconut: "Chocolate's modules with a choice of exploration scheme (random walk or Lévy-like steps)",
  maple: "Chocolate's modules under the behaviour-tree code base's laws: the flavour of behaviour trees",
  arlequin: 'neural networks in place of the six Chocolate behaviours; Chocolate conditions',
};

const DISPLAY = { chocolate: 'Chocolate', tuttifrutti: 'TuttiFrutti', coconut: 'Coconut', maple: 'Maple', arlequin: 'Arlequin' };

/// The methods of the thesis, as run-design flags.
export const PRESETS = [
  { id: 'all', label: 'All flavours, both architectures (run-design\'s default)', architectures: 'fsm,bt', flavours: ['chocolate', 'tuttifrutti', 'coconut', 'maple', 'arlequin'] },
  { id: 'chocolate', label: 'Chocolate: --fsm --chocolate', architectures: 'fsm', flavours: ['chocolate'] },
  { id: 'maple', label: 'Maple: --bt --maple', architectures: 'bt', flavours: ['maple'] },
  { id: 'tuttifrutti', label: 'TuttiFrutti: --fsm --tuttifrutti', architectures: 'fsm', flavours: ['tuttifrutti'] },
  { id: 'coconut', label: 'Coconut: --fsm --coconut', architectures: 'fsm', flavours: ['coconut'] },
  { id: 'arlequin', label: 'Arlequin: --fsm --arlequin', architectures: 'fsm', flavours: ['arlequin'] },
  { id: 'custom', label: 'Custom (as ticked below)' },
];

export function initDesignForm(catalogue) {
  const flavourNames = catalogue.flavours.map((f) => f.name);
  $('design-flavours').replaceChildren(...flavourNames.map((name) => el('label', { class: 'flavour-choice' },
    el('input', { type: 'checkbox', value: name, testid: `flavour-${name}`, checked: '' }),
    el('span', { class: 'flavour-name', text: DISPLAY[name] || name }),
    el('span', { class: 'muted small', text: FLAVOUR_NOTES[name] || '' }))));
  $('design-preset').replaceChildren(...PRESETS.map((p) => el('option', { value: p.id, text: p.label })));

  const architecture = () => (document.querySelector('input[name="design-arch"]:checked') || {}).value || 'fsm,bt';
  const method = () => $('design-method').value || 'automode';
  let methods = [];
  const flavours = () => [...document.querySelectorAll('#design-flavours input:checked')].map((i) => i.value);
  let minimum = null;
  let serial = 0;

  async function refreshMinimum() {
    const mine = ++serial;
    const query = `architectures=${encodeURIComponent(architecture())}&flavours=${encodeURIComponent(flavours().join(','))}` +
      `&method=${encodeURIComponent(method())}`;
    try {
      const space = await api(`/api/design-space?${query}`, { quiet: true });
      if (mine !== serial) return;
      if (methods.length === 0) showMethods(space.methods);
      minimum = space.minimum_budget;
      $('design-minimum').textContent = `at least ${minimum} runs for this space (${space.method}'s minimum)`;
      $('design-notes').textContent = space.notes.join(' ');
    } catch (e) {
      if (mine !== serial) return;
      minimum = null;
      $('design-minimum').textContent = '';
      $('design-notes').textContent = e.message;
    }
    checkBudget();
  }

  /// The methods the server offers, with the chosen one's line beside the list.
  function showMethods(list) {
    methods = list;
    const chosen = method();
    $('design-method').replaceChildren(...list.map((m) => el('option', { value: m.name, text: `${m.name}: ${m.title}` })));
    $('design-method').value = list.some((m) => m.name === chosen) ? chosen : 'automode';
    showSummary();
  }

  function showSummary() {
    const found = methods.find((m) => m.name === method());
    $('design-method-summary').textContent = found ? found.summary : '';
  }

  function checkBudget() {
    const budget = Number($('design-budget').value);
    $('design-budget').classList.toggle('invalid', minimum !== null && budget < minimum);
  }

  function applyPreset(id) {
    const preset = PRESETS.find((p) => p.id === id);
    if (!preset || !preset.flavours) return;
    for (const input of document.querySelectorAll('input[name="design-arch"]')) input.checked = input.value === preset.architectures;
    for (const input of document.querySelectorAll('#design-flavours input')) input.checked = preset.flavours.includes(input.value);
    refreshMinimum();
  }

  /// The preset the ticks match, or custom.
  function matchPreset() {
    const chosen = flavours().sort().join(',');
    const found = PRESETS.find((p) => p.flavours && p.architectures === architecture() && [...p.flavours].sort().join(',') === chosen);
    $('design-preset').value = found ? found.id : 'custom';
  }

  $('design-preset').addEventListener('change', () => applyPreset($('design-preset').value));
  $('design-form').addEventListener('change', (e) => {
    if (e.target.id === 'design-preset') return;
    if (e.target.id === 'design-method') { showSummary(); refreshMinimum(); return; }
    if (e.target.id !== 'design-budget' && e.target.id !== 'design-seed') { matchPreset(); refreshMinimum(); }
    checkBudget();
  });
  $('design-form').addEventListener('submit', (e) => e.preventDefault());
  $('design-budget').addEventListener('input', checkBudget);
  applyPreset('all');

  return {
    /// The body of POST /api/projects/NAME/designs.
    request() {
      const body = { architectures: architecture(), flavours: flavours().join(',') };
      if (method() !== 'automode') body.method = method();  // as run-design without --method
      const seed = $('design-seed').value.trim();
      if (seed !== '') body.seed = seed;  // as typed: a 64-bit seed would lose digits as a JS number
      return body;
    },
    budget() { return $('design-budget').value.trim(); },
    setBudget(value) { $('design-budget').value = value === null || value === undefined ? '' : String(value); checkBudget(); },
    get minimum() { return minimum; },
  };
}
