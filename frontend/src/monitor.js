// The Designs tab: the user's projects, start / stop a design, and its live status (polled):
// runs used against the budget, iteration, configurations alive, elites, convergence, best drawn;
// the project's experiments with their progress and a link to each report.
import { api } from './api.js';
import { getCatalogue } from './catalogue.js';
import { initDesignForm } from './design_form.js';
import { createGraph, renderModel } from './graph.js';
import { shortName } from './missions.js';
import { scoreSpan } from './numbers.js';
import { linePlot } from './plot.js';
import { el } from './properties.js';
import { boxPlot, initSeedTest } from './seed_test.js';
import { confirmDelete } from './confirm_dialog.js';
import { initExperiments } from './experiments.js';
import { readable } from './numbers.js';
import { download } from './download.js';
import { refreshQuota } from './quota.js';
import { clearError } from './toast.js';

const $ = (id) => document.getElementById(id);

/// The delete dialog's warning: the projects whose mission is a file of the one deleted.
function usedByWarning(name, users) {
  const one = users.length === 1;
  return `${one ? 'Project' : 'Projects'} ${users.join(', ')} ${one ? 'uses a mission file' : 'use mission files'} of ${name}: ` +
    `deleted with it, ${one ? 'it' : 'they'} will say "its mission file was deleted" and design nothing until you choose another mission.`;
}

export function initMonitor({ onWatch, onEdit, missions, onProjectsChanged = () => {} }) {
  let selected = null;
  let projectBudgets = new Map();
  let projectInfo = new Map();  // name -> the project's document as /api/projects last gave it
  let missionChoices = [];  // /api/missions: what a project's mission may be set to
  let missionShown = null;  // what the Set mission form was last filled for
  let listed = null;  // {id, state} of the newest row of the design list as last drawn
  let timer = null;
  let status = null;
  let testTarget = null;  // {project, text} of the best shown, for "Test on seeds"
  let bestDrawn = null;
  let realityShown = null;  // "project/design" whose pseudo-reality assessment is shown
  let plot = null;
  let visible = false;
  let fastUntil = 0;
  // An earlier design shown instead of the latest (its id), an experiment's ({experiment: name}:
  // the one it is making; {experiment, design: id}: that one), or null.
  let opened = null;
  const comparing = new Set();  // ids of the designs ticked for comparison
  const graph = createGraph($('best-graph'), { readOnly: true });
  const form = initDesignForm(getCatalogue());

  const directionOf = (mission) => (missions().find((m) => m.name === mission) || {}).direction || 'maximize';

  async function refreshProjects() {
    const answer = await api('/api/projects');
    const projects = Array.isArray(answer) ? answer : answer.projects || [];
    projectBudgets = new Map(projects.map((p) => [p.name, p.budget]));
    projectInfo = new Map(projects.map((p) => [p.name, p]));
    if (selected && projectBudgets.has(selected) && !$('design-budget').value) form.setBudget(projectBudgets.get(selected));
    const list = $('project-list');
    list.replaceChildren(...projects.map((p) => el('li', {
      class: p.name === selected ? 'selected' : '', testid: `project-${p.name}`,
      onclick: () => select(p.name),
    }, el('span', { text: p.name }), el('span', { class: `muted small${p.mission_problem ? ' mission-deleted' : ''}`,
      text: `${p.mission_problem ? 'mission file deleted' : p.mission ? shortName({ name: p.mission }) : 'no mission'} · ${p.budget ?? '–'}`,
      title: p.mission_problem ? `${p.mission}: ${p.mission_problem}` : p.mission || '' }))));
    if (!projects.length) list.append(el('li', { class: 'muted small', text: 'no project yet' }));
    if (!selected && projects.length) select(projects[0].name);
    showProjectMission();
    return projects;
  }

  /// The selected project's mission in the Set mission form (set-mission): any mission of the
  /// list. A mission file deleted with the project that held it is said so, the choice left open.
  function showProjectMission() {
    const p = selected ? projectInfo.get(selected) : null;
    $('project-mission-form').hidden = !p;
    if (!p) return;
    const key = JSON.stringify([p.name, p.mission, p.mission_problem, missionChoices.map((m) => m.name)]);
    if (key === missionShown) return;  // keep what the user is choosing
    missionShown = key;
    const current = p.mission_problem ? null : p.mission;
    const listed = missionChoices.some((m) => m.name === current);
    const options = missionChoices.map((m) => el('option', { value: m.name, text: `${shortName(m)} — ${m.title}`, title: m.name }));
    if (!listed) options.unshift(el('option', { value: '', text: current ? `${shortName({ name: current })} (not in the list)` : '— choose a mission —' }));
    $('project-set-mission').replaceChildren(...options);
    $('project-set-mission').value = listed ? current : '';
    const note = $('project-mission-note');
    note.textContent = p.mission_problem ? `${shortName({ name: p.mission })}: ${p.mission_problem}. Choose another mission and Set mission.` : '';
    note.className = p.mission_problem ? 'problem' : '';
    note.title = p.mission_problem ? p.mission : '';
  }

  function select(name) {
    selected = name;
    opened = null;
    comparing.clear();
    $('compare-result').replaceChildren();
    status = null;
    bestDrawn = null;
    listed = null;
    $('monitor-project').textContent = name;
    $('project-delete').disabled = false;
    form.setBudget(projectBudgets.get(name));
    showProjectMission();
    for (const li of $('project-list').children) li.classList.toggle('selected', li.dataset.testid === `project-${name}`);
    graph.elements().remove();
    poll();
    refreshDesigns();
  }

  /// What a design was started with, as `status` prints it.
  // A mission file is shown as project/file (the whole path is the design's title, on hover).
  const startedWith = (d) => `${d.architectures} · ${d.flavours}${d.method && d.method !== 'automode' ? ` · ${d.method}` : ''}` +
    ` · seed ${d.seed} · budget ${d.budget} · ${shortName({ name: d.mission || '' })}`;

  /// The list reads its rows from /designs; the newest row's state is the status box's (both come
  /// from the same storage reading, and the list is fetched again whenever they would differ).
  async function refreshDesigns() {
    if (!selected) return;
    const rows = await api(`/api/projects/${encodeURIComponent(selected)}/designs`).catch(() => []);
    listed = rows.length ? { id: rows[0].id, state: rows[0].state } : null;
    for (const id of [...comparing]) if (!rows.some((d) => d.id === id && d.best_configuration)) comparing.delete(id);
    if (typeof opened === 'number' && !rows.some((d) => d.id === opened)) opened = null;
    $('design-list').replaceChildren(...rows.map((d) => designRow(d, d === rows[0])));
    if (!rows.length) $('design-list').append(el('li', { class: 'muted small', text: 'no design yet' }));
    updateCompareButton();
  }

  /// One design: click to open it (the latest is the one shown by default); tick two finished
  /// ones to compare them; delete one that does not run.
  function designRow(d, latest) {
    const shown = opened === null ? latest : opened === d.id;
    const tick = el('input', { type: 'checkbox', testid: `compare-${d.id}`, title: 'compare this design\'s best with another one\'s',
      onclick: (e) => e.stopPropagation(),
      onchange: (e) => { if (e.target.checked) comparing.add(d.id); else comparing.delete(d.id); updateCompareButton(); } });
    tick.checked = comparing.has(d.id);
    tick.disabled = !d.best_configuration;
    const remove = el('button', { type: 'button', class: 'icon', testid: `design-delete-${d.id}`, text: '✕',
      title: d.state === 'running' ? 'a running design cannot be deleted: stop it first' : `delete design #${d.id}`,
      onclick: (e) => { e.stopPropagation(); deleteDesign(d); } });
    remove.disabled = d.state === 'running';
    return el('li', { testid: `design-${d.id}`, class: `design-row${shown ? ' opened' : ''}`, title: d.folder,
      onclick: () => openDesign(latest ? null : d.id) },
      el('span', { class: 'design-actions' }, el('span', { class: 'design-head', text: `#${d.id} ${d.state}` }),
        el('span', { class: 'spacer' }), el('label', { class: 'inline small' }, tick, 'compare'), remove),
      el('span', { class: 'muted', text: startedWith(d), title: d.mission || '' }),
      d.best_score !== null && d.best_score !== undefined ? scoreSpan(el, d.best_score, { class: 'muted' }) : '');
  }

  function openDesign(id) {
    opened = id;
    bestDrawn = null;
    graph.elements().remove();
    $('test-result').replaceChildren();
    for (const li of $('design-list').children) li.classList.toggle('opened', li.dataset.testid === `design-${id ?? (listed && listed.id)}`);
    poll();
  }

  async function deleteDesign(d) {
    const project = selected;
    const yes = await confirmDelete({ title: `Delete design #${d.id}?`,
      text: `Its race data and best control software (${startedWith(d)}) are deleted. Other designs, experiments and saved software stay.` });
    if (!yes) return;
    try { await api(`/api/projects/${encodeURIComponent(project)}/designs/${d.id}/delete`, { body: {} }); } catch { return; }
    comparing.delete(d.id);
    if (opened === d.id) opened = null;
    refreshQuota();
    await refreshDesigns();
    poll();
  }

  function updateCompareButton() {
    $('compare-run').disabled = comparing.size !== 2;
    $('compare-run').textContent = comparing.size === 2 ? `Compare #${[...comparing].join(' and #')}` : 'Compare two ticked designs';
  }

  /// The two ticked designs' bests on the same seeds: each one's box plot and the paired test.
  async function compare() {
    const ids = [...comparing].sort((a, b) => a - b);
    const seeds = $('compare-seeds').value.trim();
    const out = $('compare-result');
    out.replaceChildren(document.createTextNode(`scoring #${ids.join(' and #')} on seeds ${seeds}…`));
    try {
      const answer = await api(`/api/projects/${encodeURIComponent(selected)}/compare`, { body: { designs: ids, seeds }, quiet: true });
      const w = answer.wilcoxon;
      const verdict = w.note ? w.note
        : `paired Wilcoxon p = ${readable(w.p_value)}${w.p_value < 0.05 ? ` — #${w.estimate > 0 ? ids[0] : ids[1]} scores ${w.estimate > 0 ? 'higher' : 'lower'} (median difference ${readable(w.estimate)})` : ' — no difference at 5 %'}`;
      // One scale for both, so the boxes compare by eye.
      const all = answer.designs.flatMap((d) => d.runs.map((r) => r.score));
      const range = [Math.min(...all), Math.max(...all)];
      out.replaceChildren(...answer.designs.map((d) => el('div', { class: 'compare-side', testid: `compare-side-${d.design}` },
        el('span', { text: `#${d.design}: mean ${readable(d.mean)} · sd ${readable(d.sd)}` }), boxPlot(d.runs, 200, 48, range))),
      el('div', { testid: 'compare-verdict', text: `${verdict} (seeds ${answer.seeds})` }));
    } catch (e) {
      out.replaceChildren(el('div', { class: 'error', text: e.message }));
    }
  }

  const experiments = initExperiments({ project: () => selected, onChanged: () => { fastUntil = Date.now() + 10000; poll(); },
    onFollow: (name, design) => openDesign(design ? { experiment: name, design } : { experiment: name }) });
  const renderExperiments = (s) => experiments.render(s.experiments || []);

  function renderStatus(s) {
    renderExperiments(s);
    const design = s.design;
    const progress = s.progress || {};
    if (!design) {
      for (const id of ['iteration', 'alive']) $(id).textContent = '–';
      $('runs-used').textContent = s.budget ? `0 / ${s.budget}` : '–';
      $('design-state').textContent = 'no design yet';
      $('design-info').textContent = '';
      renderElites([], 'no design yet: start one above');
      if (plot) plot.setData([], []);
      showConvergence(false);
      $('best-score').textContent = 'no configuration yet';
      clearBest();
      for (const id of ['watch-best', 'edit-best', 'test-run', 'argos-best']) $(id).disabled = true;
      refreshAssessment(null, false);
      testTarget = null;
      $('argos-result').replaceChildren();
      $('design-start').disabled = false;
      $('design-stop').disabled = true;
      allowMissionChange(true);
      showResumable(null);
      return;
    }
    $('runs-used').textContent = `${progress.experiments_used ?? 0} / ${design.budget}`;
    $('iteration').textContent = progress.total_iterations ? `${progress.iteration} / ${progress.total_iterations}` : String(progress.iteration ?? '–');
    // As `swarmdesign status` counts them: the configurations of the current race, and how
    // many of those are still racing.
    const alive = progress.race_alive;
    const inRace = progress.race_configurations;
    $('alive').textContent = alive === undefined ? '–' : (inRace !== undefined && inRace !== alive ? `${alive} racing of ${inRace}` : String(alive));
    // A cluster project's design runs as a Slurm job: its state, and the last problem in one line.
    const job = s.cluster_job;
    const slurm = job ? ` · Slurm job ${job.job_id ?? '(not submitted)'}${job.slurm_state ? ` ${job.slurm_state}` : ''}${job.note ? ` · ${job.note}` : ''}` : '';
    // Iterated F-Race ends when its budget is spent or cannot pay another race (which of the two
    // depends on the seed): the normal end, not an error.
    const spent = design.state === 'finished' && /^(not enough budget|budget exhausted)/i.test(progress.finish_reason || '');
    const reason = spent ? '' : progress.finish_reason ? ` · ${progress.finish_reason}` : '';
    $('design-state').textContent = `${spent ? 'finished: budget spent' : design.state}${s.running_here ? ' (here)' : ''}${slurm}${reason}`;
    $('design-state').title = progress.finish_reason ? `finished because: ${progress.finish_reason}` : '';
    // Start and Stop act on the project's latest design, whichever is shown.
    const latestState = opened === null ? design.state : listed && listed.state;
    $('design-start').disabled = latestState === 'running';
    $('design-stop').disabled = latestState !== 'running';
    allowMissionChange(latestState !== 'running');
    showResumable(opened === null ? design : null);

    const note = opened === null ? ''
      : opened.design ? `Showing design #${design.id} of experiment ${opened.experiment}. `
        : opened.experiment ? `Showing the design experiment ${opened.experiment} is making. ` : `Showing earlier design #${design.id}. `;
    $('design-info').replaceChildren(...(opened === null ? [] : [el('span', { class: 'opened-note', testid: 'opened-note' },
      note, el('button', { type: 'button', class: 'link', testid: 'show-latest', text: 'show the latest', onclick: () => openDesign(null) }))]),
    document.createTextNode(`${opened && opened.experiment ? `Experiment design #${design.id}` : `Design #${design.id}`}: ${startedWith(design)}`));
    $('design-info').title = design.mission || '';
    renderElites(progress.elites || []);
    // Convergence: the best elite's mean over all its runs at the end of each iteration.
    const points = s.convergence || [];
    if (!plot) plot = linePlot($('convergence-plot'), { xLabel: 'iteration', yLabel: 'best elite mean', height: 200, points: true, integerX: true });
    plot.setData(points.map((p) => p.iteration), points.map((p) => p.best_score));
    showConvergence(points.length > 0);

    const best = (progress.best && progress.best.configuration) || design.best_configuration;
    const score = (progress.best && progress.best.mean_score) ?? design.best_score;
    const runs = progress.best ? ` over ${progress.best.runs} runs` : '';
    $('best-score').replaceChildren(...(best
      ? [document.createTextNode('mean score '), scoreSpan(el, score, { testid: 'best-mean' }), document.createTextNode(`${runs} (${directionOf(design.mission)})`)]
      : [document.createTextNode('no configuration yet')]));
    if (!testTarget || testTarget.text !== best) $('argos-result').replaceChildren();
    testTarget = best ? { project: selected, text: best } : null;
    // Tests and exports run on the project's mission: not for an experiment's design (its report assesses it).
    const ownDesign = !(opened && opened.experiment);
    $('test-run').disabled = !best || !ownDesign;
    $('argos-best').disabled = !best || !ownDesign;
    refreshAssessment(design, Boolean(design.best_configuration) && ownDesign && design.state !== 'running');
    for (const id of ['watch-best', 'edit-best']) {
      $(id).disabled = !best;
      $(id).dataset.text = best || '';
      $(id).dataset.mission = design.mission || '';
    }
    // No best yet (a design just started, or a fresh one after another): no drawing either, not
    // the previous design's under "no configuration yet".
    if (!best && bestDrawn !== null) clearBest();
    if (best && best !== bestDrawn) {
      bestDrawn = best;
      api('/api/parse', { body: { text: best }, quiet: true })
        .then((answer) => { if (bestDrawn === best) { renderModel(graph, answer.software, { relayout: true }); graph.fit(undefined, 10); } })
        .catch(() => {});
    }
  }

  function clearBest() {
    bestDrawn = null;
    graph.elements().remove();
  }

  /// The server refuses a new mission while a design runs (it keeps the one it started with).
  function allowMissionChange(allowed) {
    $('project-set-mission-button').disabled = !allowed;
    $('project-set-mission-button').title = allowed ? "make it the project's mission (swarmdesign set-mission)"
      : 'a design of this project is running: stop it first (it keeps the mission it started with)';
  }

  function showConvergence(any) {
    $('convergence-plot').hidden = !any;
    $('convergence-empty').hidden = any;
  }

  /// An interrupted (or failed) design resumes with what it was started with, whatever the form
  /// says, unless the user gives it up (fresh): the button and a note say which will happen.
  function showResumable(design) {
    const resumable = !!design && (design.state === 'interrupted' || design.state === 'failed');
    const fresh = $('design-fresh').checked;
    $('design-resume').hidden = !resumable;
    $('design-resume-text').textContent = resumable
      ? `Design #${design.id} is ${design.state}: Start resumes it as it was started (${startedWith(design)}). ` : '';
    $('design-start').textContent = resumable && !fresh ? `Resume design #${design.id}` : 'Start design';
    $('design-choices').disabled = resumable && !fresh;
    if (!resumable) $('design-fresh').checked = false;
  }

  function renderElites(elites, empty = 'none yet: the first race is under way') {
    $('elites').tBodies[0].replaceChildren(...elites.map((c) => el('tr', { testid: `elite-${c.id}` },
      el('td', { text: String(c.id) }), el('td', {}, scoreSpan(el, c.mean_score, { class: 'elite-mean' })),
      el('td', { class: 'elite-runs', text: String(c.runs) }), el('td', { class: 'conf', text: c.configuration }))));
    if (!elites.length) $('elites').tBodies[0].append(el('tr', {}, el('td', { colspan: '4', class: 'muted small', text: empty })));
  }

  async function poll() {
    clearTimeout(timer);
    if (!selected) return;
    const name = selected;
    let running = false;
    try {
      const wanted = opened;
      const base = `/api/projects/${encodeURIComponent(name)}`;
      // Without the race log (every configuration of every race): its counts are in progress.
      const url = wanted === null ? `${base}/status?race_log=false`
        : wanted.design ? `${base}/experiments/${encodeURIComponent(wanted.experiment)}/designs/${wanted.design}?race_log=false`
          : wanted.experiment ? `${base}/experiments/${encodeURIComponent(wanted.experiment)}/current?race_log=false`
          : `${base}/status?design=${wanted}&race_log=false`;
      let s;
      try {
        s = await api(url, { quiet: true });
      } catch (e) {
        // The experiment's designs are all done (or it went): back to the project's latest design.
        if (wanted && wanted.experiment && e.status === 404 && wanted === opened) { opened = null; poll(); return; }
        throw e;
      }
      // An experiment's design brings no experiment list: it is asked for beside it.
      if (wanted && wanted.experiment) s.experiments = await api(`${base}/experiments`, { quiet: true }).catch(() => (status ? status.experiments : []));
      if (name !== selected || wanted !== opened) return;
      const was = status && status.design && status.design.state;
      status = s;
      renderStatus(s);
      // Its mission file deleted meanwhile (from another tab or the CLI): the form says so.
      const known = projectInfo.get(name);
      if (known && s.mission_problem !== undefined && (s.mission_problem || null) !== (known.mission_problem || null)) refreshProjects().catch(() => {});
      running = !!(s.design && s.design.state === 'running') || (s.experiments || []).some((e) => e.state === 'running');
      const stale = opened !== null ? false
        : s.design ? !listed || listed.id !== s.design.id || listed.state !== s.design.state : listed !== null;
      if (stale || (s.design && was && was !== s.design.state)) refreshDesigns();
    } catch (e) {
      $('design-state').textContent = e.message;
    }
    if (visible || running) timer = setTimeout(poll, running || Date.now() < fastUntil ? 1000 : 5000);
  }

  // A project's budget below Iterated F-Race's least for the default space (every flavour, both
  // architectures) can still design in a smaller space: a warning, not a refusal.
  let leastBudget = null;
  api('/api/design-space', { quiet: true }).then((space) => { leastBudget = space.minimum_budget; budgetNote(); }).catch(() => {});
  function budgetNote() {
    const budget = Number($('project-budget').value);
    const low = leastBudget !== null && budget > 0 && budget < leastBudget;
    $('project-budget-note').textContent = low
      ? `below ${leastBudget}, the least Iterated F-Race needs for every flavour and both architectures: only a smaller design space fits`
      : '';
    $('project-budget-note').classList.toggle('warning', low);
  }
  $('project-budget').addEventListener('input', budgetNote);

  $('project-form').addEventListener('submit', async (e) => {
    e.preventDefault();
    const name = $('project-name').value.trim();
    const body = { name, mission: $('project-mission').value, budget: Number($('project-budget').value) };
    try { await api('/api/projects', { body }); } catch { return; }
    $('project-name').value = '';
    selected = null;
    await refreshProjects();
    select(name);
  });
  $('design-start').addEventListener('click', async () => {
    if (!selected) return;
    const name = selected;
    const resume = !$('design-resume').hidden && !$('design-fresh').checked;
    try {
      const budget = form.budget();
      if (!resume && budget !== '' && budget !== String(projectBudgets.get(name) ?? '')) {
        const project = await api(`/api/projects/${encodeURIComponent(name)}/budget`, { body: { budget } });
        projectBudgets.set(name, project.budget);
      }
      const body = resume ? {} : { ...form.request(), fresh: $('design-fresh').checked };
      await api(`/api/projects/${encodeURIComponent(name)}/designs`, { body });
    } catch { return; }
    refreshQuota();  // its budget is counted in today's runs
    fastUntil = Date.now() + 10000;
    refreshDesigns();
    refreshProjects().catch(() => {});  // the budget the form may have set
    poll();
  });
  $('project-mission-form').addEventListener('submit', async (e) => {
    e.preventDefault();
    const name = selected;
    if (!name) return;
    const note = $('project-mission-note');
    let project;
    try {
      project = await api(`/api/projects/${encodeURIComponent(name)}/mission`, { body: { mission: $('project-set-mission').value }, quiet: true });
    } catch (err) {
      note.textContent = err.message;
      note.className = 'error';
      return;
    }
    clearError();  // a refused Start for want of a mission is stale
    await refreshProjects();
    note.textContent = `mission set to ${shortName({ name: project.mission })}`;
    note.className = 'done';
    poll();
  });
  $('design-fresh').addEventListener('change', () => { if (status) showResumable(status.design); });
  $('design-stop').addEventListener('click', async () => {
    if (!selected) return;
    try { await api(`/api/projects/${encodeURIComponent(selected)}/designs/stop`, { body: {} }); } catch { /* shown */ }
    fastUntil = Date.now() + 10000;
    poll();
  });
  initSeedTest(() => testTarget);
  // The reality gap of the design shown: its last assessment in a pseudo-reality, and a new one.
  function showAssessment(doc) {
    const out = $('reality-result');
    if (!doc) { out.replaceChildren(); return; }
    const s = doc.software[0];
    const pct = s.relative_drop === null || s.relative_drop === undefined ? '' : ` (${(100 * s.relative_drop).toFixed(1)} %)`;
    const p = s.p_value >= 0.001 ? s.p_value.toFixed(3) : s.p_value.toExponential(1);
    const range = (xs) => (xs.length > 1 ? `${xs[0]}-${xs[xs.length - 1]}` : String(xs[0]));
    out.replaceChildren(
      el('div', { testid: 'reality-where', text: `pseudo-reality ${doc.pseudo_reality.name}, samples ${range(doc.samples)}, seeds ${range(doc.seeds)}` }),
      el('div', {}, 'design model mean ', scoreSpan(el, s.design_mean, { testid: 'reality-design-mean' }),
        ', pseudo-reality mean ', scoreSpan(el, s.pseudo_reality_mean, { testid: 'reality-mean' })),
      el('div', { testid: 'reality-drop' }, el('strong', { text: 'drop ' }), scoreSpan(el, s.drop),
        ` [${readable(s.drop_ci95[0])}, ${readable(s.drop_ci95[1])}]${pct}, Wilcoxon p = ${p}`));
  }
  async function refreshAssessment(design, enabled) {
    $('reality-run').disabled = !enabled;
    const key = enabled ? `${selected}/${design.id}` : null;
    if (key === realityShown) return;
    realityShown = key;
    showAssessment(null);
    if (!key) return;
    try {
      const doc = await api(`/api/projects/${encodeURIComponent(selected)}/designs/${design.id}/assessment`, { quiet: true });
      if (realityShown === key) showAssessment(doc);
    } catch { /* not assessed yet */ }
  }
  api('/api/pseudo-realities', { quiet: true }).then((list) => {
    $('reality-spec').replaceChildren(...list.map((p) => el('option', { value: p.name, text: p.name, title: p.description })));
    const around = list.find((p) => p.name === 'sampled-around');
    if (around) $('reality-spec').value = around.name;
  }).catch(() => {});
  $('reality-form').addEventListener('submit', async (e) => {
    e.preventDefault();
    // The design whose assessment is shown (the status may be reloading meanwhile).
    const key = realityShown;
    if (!key) return;
    const [project, id] = [key.slice(0, key.lastIndexOf('/')), key.slice(key.lastIndexOf('/') + 1)];
    $('reality-run').disabled = true;
    $('reality-result').textContent = 'assessing…';
    try {
      const doc = await api(`/api/projects/${encodeURIComponent(project)}/designs/${id}/assessment`,
        { body: { pseudo_reality: $('reality-spec').value, samples: $('reality-samples').value }, quiet: true });
      if (realityShown === key) showAssessment(doc);
    } catch (err) {
      if (realityShown === key) $('reality-result').textContent = `refused: ${err.message}`;
    } finally {
      $('reality-run').disabled = false;
    }
  });
  $('compare-form').addEventListener('submit', (e) => { e.preventDefault(); if (comparing.size === 2) compare(); });
  $('project-delete').addEventListener('click', async () => {
    const name = selected;
    if (!name) return;
    // Asked now, not from the list drawn earlier: another tab may have set a mission since.
    const current = (await api('/api/projects', { quiet: true }).catch(() => [])).find((p) => p.name === name) || {};
    const users = current.mission_used_by || [];
    const yes = await confirmDelete({ title: `Delete project ${name}?`, typeToConfirm: name,
      text: 'Its designs, experiments, reports, uploaded missions and saved control software are deleted for good. ' +
        `Your other projects stay${users.length ? ', but not the mission files they use from this one' : ''}.`,
      warning: users.length ? usedByWarning(name, users) : null });
    if (!yes) return;
    try { await api(`/api/projects/${encodeURIComponent(name)}/delete`, { body: { confirm: name } }); } catch { return; }
    selected = null;
    $('monitor-project').textContent = 'no project selected';
    $('project-delete').disabled = true;
    $('design-list').replaceChildren();
    $('compare-result').replaceChildren();
    const left = await refreshProjects();
    if (!left.length) renderStatus({});
    refreshQuota();
    await onProjectsChanged();
    // The first project left without a mission, to choose it another one.
    if (users.length && left.some((p) => p.name === users[0])) select(users[0]);
  });
  // The best shown, for ARGoS3-AutoMoDe: the mission's .argos file downloads, and the command
  // line that runs it (the string its flavour's code base reads) is shown to copy.
  $('argos-best').addEventListener('click', async () => {
    const target = testTarget;
    if (!target) return;
    const out = $('argos-result');
    try {
      const a = await api(`/api/projects/${encodeURIComponent(target.project)}/argos`, { body: { text: target.text }, quiet: true });
      download(new Blob([a.experiment], { type: 'application/xml' }), a.file_name);
      out.replaceChildren(
        el('div', { text: `${a.file_name} saved (set its library paths: ${a.loop_functions_dir}, ${a.automode_library}).` }),
        ...(a.command
          ? [el('div', { text: `Run it with ${a.argos.reader}:` }), el('code', { class: 'argos-command', testid: 'argos-command', text: a.command })]
          : [el('div', { class: 'error', testid: 'argos-refused', text: `No ARGoS3-AutoMoDe code base reads this control software: ${a.argos.refused}` })]),
        ...a.notes.map((n) => el('div', { class: 'muted', text: n })));
    } catch (e) {
      out.replaceChildren(el('div', { class: 'error', text: e.message }));
    }
  });
  $('watch-best').addEventListener('click', () => {
    const b = $('watch-best');
    if (b.dataset.text) onWatch(b.dataset.text, b.dataset.mission);
  });
  $('edit-best').addEventListener('click', () => {
    const b = $('edit-best');
    if (b.dataset.text) onEdit(b.dataset.text);
  });

  return {
    setMissions(list) {
      missionChoices = list;
      showProjectMission();
      $('project-mission').replaceChildren(...list.map((m) => el('option', { value: m.name, text: `${shortName(m)} — ${m.title}`, title: m.name })));
    },
    shown() { visible = true; refreshProjects().catch(() => {}); graph.resize(); },
    hidden() { visible = false; },
    select,
    get status() { return status; },
    convergence() { return plot ? { xs: [...plot.plot.data[0]], ticks: plot.xTicks() } : null; },
    bestDrawing() { return { nodes: graph.nodes().length, drawn: bestDrawn }; },
  };
}
