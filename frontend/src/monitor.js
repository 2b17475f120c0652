// The Designs tab: the user's projects, start / stop a design, and its live status (polled):
// runs used against the budget, iteration, configurations alive, elites, convergence, best drawn;
// the project's experiments with their progress and a link to each report.
import { api } from './api.js';
import { createGraph, renderModel } from './graph.js';
import { linePlot } from './plot.js';
import { el } from './properties.js';

const $ = (id) => document.getElementById(id);

export function initMonitor({ onWatch, missions }) {
  let selected = null;
  let timer = null;
  let status = null;
  let bestDrawn = null;
  let plot = null;
  let visible = false;
  let fastUntil = 0;
  const graph = createGraph($('best-graph'), { readOnly: true });

  const directionOf = (mission) => (missions().find((m) => m.name === mission) || {}).direction || 'maximize';

  async function refreshProjects() {
    const answer = await api('/api/projects');
    const projects = Array.isArray(answer) ? answer : answer.projects || [];
    const list = $('project-list');
    list.replaceChildren(...projects.map((p) => el('li', {
      class: p.name === selected ? 'selected' : '', testid: `project-${p.name}`,
      onclick: () => select(p.name),
    }, el('span', { text: p.name }), el('span', { class: 'muted small', text: `${p.mission || 'no mission'} · ${p.budget ?? '–'}` }))));
    if (!projects.length) list.append(el('li', { class: 'muted small', text: 'no project yet' }));
    if (!selected && projects.length) select(projects[0].name);
    return projects;
  }

  function select(name) {
    selected = name;
    status = null;
    bestDrawn = null;
    $('monitor-project').textContent = name;
    for (const li of $('project-list').children) li.classList.toggle('selected', li.dataset.testid === `project-${name}`);
    graph.elements().remove();
    poll();
    refreshDesigns();
  }

  async function refreshDesigns() {
    if (!selected) return;
    const rows = await api(`/api/projects/${encodeURIComponent(selected)}/designs`).catch(() => []);
    $('design-list').replaceChildren(...rows.map((d) => el('li', {},
      el('span', { text: `#${d.id} ${d.state}` }),
      el('span', { class: 'muted', text: `${d.mission} · ${d.budget}${d.best_score !== null && d.best_score !== undefined ? ` · best ${d.best_score}` : ''}` }))));
  }

  /// The project's experiments (swarmdesign experiment): progress and a link to the report page.
  function renderExperiments(s) {
    const list = s.experiments || [];
    $('experiment-list').replaceChildren(...list.map((e) => {
      const current = e.current && e.state !== 'finished'
        ? ` · ${e.state === 'running' ? 'now' : 'next'} ${e.current.mission} / ${e.current.condition} #${e.current.replicate}` : '';
      const href = `/api/projects/${encodeURIComponent(selected)}/experiments/${encodeURIComponent(e.name)}/report`;
      return el('li', { testid: `experiment-${e.name}` },
        el('span', { text: `${e.name} · ${e.state}` }),
        el('span', { class: 'muted', text: `${e.designs_done} / ${e.designs} designs${current}` }),
        el('a', { href, target: '_blank', rel: 'noopener', testid: `report-${e.name}`, text: 'report' }));
    }));
    if (!list.length) $('experiment-list').append(el('li', { class: 'muted small', text: 'none (swarmdesign experiment)' }));
  }

  function lastRace(s) { return s.race_log && s.race_log.length ? s.race_log[s.race_log.length - 1] : null; }

  function renderStatus(s) {
    renderExperiments(s);
    const design = s.design;
    const progress = s.progress || {};
    if (!design) {
      for (const id of ['iteration', 'alive']) $(id).textContent = '–';
      $('runs-used').textContent = s.budget ? `0 / ${s.budget}` : '–';
      $('design-state').textContent = 'no design yet';
      $('design-start').disabled = false;
      $('design-stop').disabled = true;
      return;
    }
    $('runs-used').textContent = `${progress.experiments_used ?? 0} / ${design.budget}`;
    $('iteration').textContent = progress.total_iterations ? `${progress.iteration} / ${progress.total_iterations}` : String(progress.iteration ?? '–');
    const race = lastRace(s);
    const alive = race ? race.configurations.filter((c) => c.eliminated_after === null || c.eliminated_after === undefined).length : progress.race_configurations;
    $('alive').textContent = alive === undefined ? '–' : String(alive);
    // A cluster project's design runs as a Slurm job: its state, and the last problem in one line.
    const job = s.cluster_job;
    const slurm = job ? ` · Slurm job ${job.job_id ?? '(not submitted)'}${job.slurm_state ? ` ${job.slurm_state}` : ''}${job.note ? ` · ${job.note}` : ''}` : '';
    $('design-state').textContent = `${design.state}${s.running_here ? ' (here)' : ''}${slurm}${progress.finish_reason ? ` · ${progress.finish_reason}` : ''}`;
    $('design-start').disabled = design.state === 'running';
    $('design-stop').disabled = design.state !== 'running';

    // A race lists its elites (best first) once it is over; the race under way lists none yet.
    const finished = (s.race_log || []).filter((r) => r.elites && r.elites.length);
    const members = (r) => new Map(r.configurations.map((c) => [c.id, c]));
    const latest = finished.length ? finished[finished.length - 1] : null;
    const elites = latest ? latest.elites.map((id) => members(latest).get(id)).filter(Boolean) : [];
    $('elites').tBodies[0].replaceChildren(...elites.map((c) => el('tr', {},
      el('td', { text: String(c.id) }), el('td', { text: String(Math.round(c.mean_score * 1000) / 1000) }), el('td', { text: String(c.runs) }),
      el('td', { class: 'conf', text: c.configuration }))));
    $('elites').dataset.iteration = latest ? String(latest.iteration) : '';
    // Convergence: the best elite's mean score at the end of each race.
    const xs = [];
    const ys = [];
    for (const r of finished) {
      const best = members(r).get(r.elites[0]);
      if (best) { xs.push(r.iteration); ys.push(best.mean_score); }
    }
    if (!plot) plot = linePlot($('convergence-plot'), { xLabel: 'iteration', yLabel: 'best elite mean score', height: 200, points: true });
    plot.setData(xs, ys);

    const best = (progress.best && progress.best.configuration) || design.best_configuration;
    const score = (progress.best && progress.best.mean_score) ?? design.best_score;
    $('best-score').textContent = best ? `mean score ${score} (${directionOf(design.mission)})` : 'no configuration yet';
    $('watch-best').disabled = !best;
    $('watch-best').dataset.text = best || '';
    $('watch-best').dataset.mission = design.mission || '';
    if (best && best !== bestDrawn) {
      bestDrawn = best;
      api('/api/parse', { body: { text: best }, quiet: true })
        .then((answer) => { if (bestDrawn === best) { renderModel(graph, answer.software, { relayout: true }); graph.fit(undefined, 10); } })
        .catch(() => {});
    }
  }

  async function poll() {
    clearTimeout(timer);
    if (!selected) return;
    const name = selected;
    let running = false;
    try {
      const s = await api(`/api/projects/${encodeURIComponent(name)}/status`, { quiet: true });
      if (name !== selected) return;
      const was = status && status.design && status.design.state;
      status = s;
      renderStatus(s);
      running = !!(s.design && s.design.state === 'running') || (s.experiments || []).some((e) => e.state === 'running');
      if (s.design && was && was !== s.design.state) refreshDesigns();
    } catch (e) {
      $('design-state').textContent = e.message;
    }
    if (visible || running) timer = setTimeout(poll, running || Date.now() < fastUntil ? 1000 : 5000);
  }

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
    try { await api(`/api/projects/${encodeURIComponent(selected)}/designs`, { body: {} }); } catch { return; }
    fastUntil = Date.now() + 10000;
    refreshDesigns();
    poll();
  });
  $('design-stop').addEventListener('click', async () => {
    if (!selected) return;
    try { await api(`/api/projects/${encodeURIComponent(selected)}/designs/stop`, { body: {} }); } catch { /* shown */ }
    fastUntil = Date.now() + 10000;
    poll();
  });
  $('watch-best').addEventListener('click', () => {
    const b = $('watch-best');
    if (b.dataset.text) onWatch(b.dataset.text, b.dataset.mission);
  });

  return {
    setMissions(list) {
      $('project-mission').replaceChildren(...list.map((m) => el('option', { value: m.name, text: `${m.name} — ${m.title}` })));
    },
    shown() { visible = true; refreshProjects().catch(() => {}); graph.resize(); },
    hidden() { visible = false; },
    select,
  };
}
