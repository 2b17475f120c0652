// The report document (src/experiments/REPORT_FORMAT.md) with the look-ups every section needs,
// and the colours that stay with a condition across all plots.

// Okabe–Ito: distinguishable with colour-blindness and in grey print (yellow left out: too pale on white).
const CONDITION_COLOURS = ['#0072B2', '#E69F00', '#009E73', '#CC79A7', '#56B4E9', '#D55E00', '#000000'];

// Architectures in greys: hues belong to conditions, so no bar reads as a condition.
export const ARCHITECTURE_COLOURS = { fsm: '#4a4a4a', bt: '#a6a6a6', nn: '#dedede' };
export const ARCHITECTURE_NAMES = { fsm: 'finite-state machine', bt: 'behaviour tree', nn: 'neural network' };

export function isMaximised(mission) { return /^max/i.test(mission.direction || ''); }

export function directionText(mission) {
  return isMaximised(mission) ? 'higher is better' : 'lower is better';
}

export function indexReport(data) {
  const missions = data.missions || [];
  const conditions = data.conditions || [];
  const designs = data.designs || [];
  const colourByCondition = new Map(conditions.map((c, i) => [c.name, CONDITION_COLOURS[i % CONDITION_COLOURS.length]]));
  const designById = new Map(designs.map((d) => [d.id, d]));
  const missionByName = new Map(missions.map((m) => [m.name, m]));
  const conditionByName = new Map(conditions.map((c) => [c.name, c]));
  return {
    data,
    experiment: data.experiment || {},
    catalogue: data.catalogue || null,
    missions,
    conditions,
    designs,
    colourOf: (condition) => colourByCondition.get(condition) || '#555555',
    design: (id) => designById.get(id) || null,
    mission: (name) => missionByName.get(name) || { name, direction: 'maximise' },
    condition: (name) => conditionByName.get(name) || { name, label: '', per_mission: {} },
    designsOf: (mission, condition) => designs.filter((d) => d.mission === mission && d.condition === condition),
    box: (mission, condition) => (data.boxes || []).find((b) => b.mission === mission && b.condition === condition) || null,
  };
}
