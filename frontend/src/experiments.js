// Experiments in the Designs tab: the project's experiments, live (each poll of the monitor
// brings them), with the design being made and its race so far, Stop and Resume, the report and
// its data; and a form that starts one as `swarmdesign experiment` does: one of the thesis'
// protocols or the user's own protocol file, with the CLI's choices (missions, designs per
// condition, budget scale, assessment seeds, EvoStick), planned first.
import { api } from './api.js';
import { readable } from './numbers.js';
import { el } from './properties.js';
import { quotaRefused, refreshQuota } from './quota.js';
import { clearError, showError } from './toast.js';

const $ = (id) => document.getElementById(id);

/// "30 s", "12 min", "3.4 h", "2.1 days": as `swarmdesign experiment --dry-run` says it.
export function durationText(seconds) {
  if (seconds < 120) return `${Math.round(seconds)} s`;
  if (seconds < 2 * 3600) return `${Math.round(seconds / 60)} min`;
  if (seconds < 3 * 86400) return `${(seconds / 3600).toFixed(1)} h`;
  return `${(seconds / 86400).toFixed(1)} days`;
}

function estimateText(estimate) {
  const perMission = estimate.missions.map((m) => `${m.mission}: ${m.runs.toLocaleString('en')} runs at ${(m.seconds_per_run * 1000).toFixed(2)} ms`).join(' · ');
  return `about ${durationText(estimate.seconds)} on this server (${estimate.threads} threads, speed measured now; simulation only) — ${perMission}`;
}

export function initExperiments({ project, onChanged, onFollow }) {
  let protocols = [];
  let ownText = null;  // the user's protocol file, as read
  let startedHere = null;  // the experiment the message under the form says was started

  const chosen = () => $('exp-protocol').value;
  const current = () => (chosen() === 'own' ? null : protocols.find((p) => p.name === chosen()));

  /// The missions of the chosen protocol, each ticked: unticked ones are left out (--missions).
  function showMissions() {
    const p = current();
    $('exp-own').hidden = chosen() !== 'own';
    $('exp-evostick-row').hidden = chosen() === 'own';
    const missions = p ? p.protocol.missions : [];
    $('exp-missions').replaceChildren(...missions.map((m) => el('label', { class: 'inline small' },
      el('input', { type: 'checkbox', value: m.mission, checked: '', testid: `exp-mission-${m.mission}` }),
      `${m.mission} (${m.conditions.map((c) => c.name).join(', ')})`)));
    // Left empty, each number is the protocol's own.
    $('exp-designs').placeholder = p ? String(p.protocol.designs) : 'file\'s';
    $('exp-seeds').placeholder = p ? String(p.protocol.assessment_seeds) : 'file\'s';
    $('exp-scale').placeholder = p ? String(p.protocol.budget_scale) : 'file\'s';
    $('exp-plan').replaceChildren();
  }

  function request(dryRun) {
    // Planning also measures how long it would take on the server (the CLI's --dry-run).
    const body = dryRun ? { dry_run: true, estimate: true } : { dry_run: false };
    if (chosen() === 'own') {
      if (!ownText) throw new Error('choose your protocol file (JSON, as src/experiments/README.md shows)');
      body.text = ownText;
    } else {
      body.protocol = chosen();
      body.evostick = $('exp-evostick').checked;
      body.missions = [...$('exp-missions').querySelectorAll('input:checked')].map((i) => i.value);
      if (!body.missions.length) throw new Error('tick at least one mission');
    }
    const number = (id, key, parse) => { const v = $(id).value.trim(); if (v !== '') body[key] = parse(v); };
    number('exp-designs', 'designs', (v) => Number.parseInt(v, 10));
    number('exp-seeds', 'assessment_seeds', (v) => Number.parseInt(v, 10));
    number('exp-scale', 'budget_scale', Number);
    // Every final design also assessed in a pseudo-reality (experiment --pseudo-reality).
    const reality = $('exp-reality').value.trim();
    if (reality) body.pseudo_reality = reality;
    number('exp-reality-samples', 'pseudo_reality_samples', (v) => Number.parseInt(v, 10));
    const name = $('exp-name').value.trim();
    if (name) body.name = name;
    return body;
  }

  async function send(dryRun) {
    const out = $('exp-plan');
    let body;
    try { body = request(dryRun); } catch (e) { out.replaceChildren(el('div', { class: 'error', text: e.message })); return; }
    try {
      const answer = await api(`/api/projects/${encodeURIComponent(project())}/experiments`, { body, quiet: true });
      if (dryRun) {
        const conditions = new Set(answer.designs.map((d) => d.condition));
        out.replaceChildren(el('div', { testid: 'exp-plan-summary',
          text: `${answer.protocol.name}: ${answer.designs.length} designs (${conditions.size} conditions × ${answer.protocol.missions.length} missions × ${answer.protocol.designs}), ${answer.design_runs.toLocaleString('en')} design runs and ${answer.assessment_runs.toLocaleString('en')} assessment runs` }),
        el('div', { testid: 'exp-plan-estimate', text: estimateText(answer.estimate) }),
        ...answer.notes.map((n) => el('div', { class: 'muted', text: n })));
      } else {
        startedHere = answer.already_finished ? null : answer.experiment.name;
        out.replaceChildren(el('div', { testid: 'exp-started', text: `${answer.experiment.name} ${answer.already_finished ? 'had already finished' : answer.resumed ? 'resumed' : 'started'} ${answer.where === 'slurm' ? 'as a Slurm job array' : 'on this server'}` }),
          ...answer.notes.map((n) => el('div', { class: 'muted', text: n })));
        clearError();  // a refusal shown before is stale
        refreshQuota();  // its plan's runs are counted in today's
        onChanged();
      }
    } catch (e) {
      quotaRefused(e);
      out.replaceChildren(el('div', { class: 'error', testid: 'exp-error', text: e.message }));
    }
  }

  async function act(name, verb) {
    try { await api(`/api/projects/${encodeURIComponent(project())}/experiments/${encodeURIComponent(name)}/${verb}`, { body: {} }); } catch { return; }
    onChanged();
  }

  /// The designs an experiment has made (its report's), each to open in the monitor.
  async function chooseDesign(name) {
    const href = `/api/projects/${encodeURIComponent(project())}/experiments/${encodeURIComponent(name)}/report.json`;
    let report;
    try { report = await api(href, { quiet: true }); } catch (e) { showError(e.message); return; }
    const dialog = el('dialog', { class: 'confirm-dialog', testid: 'exp-designs-dialog' });
    const open = (id) => { dialog.close(); onFollow(name, id); };
    const rows = report.designs.map((d) => el('tr', { testid: `exp-design-row-${d.id}` },
      el('td', { text: `#${d.id}` }), el('td', { text: d.mission }), el('td', { text: `${d.condition} #${d.replicate}` }),
      el('td', { text: readable(d.score) }),
      el('td', {}, el('button', { type: 'button', class: 'small', testid: `exp-open-${d.id}`, text: 'Open', onclick: () => open(d.id) }))));
    dialog.append(el('div', { class: 'stack' },
      el('strong', { text: `Designs of ${name}` }),
      el('p', { class: 'small muted', text: 'Each with its mean score on the assessment seeds; open one to see its race and best in the monitor.' }),
      el('table', { class: 'admin-table' }, el('thead', {}, el('tr', {}, ...['', 'mission', 'condition', 'score', ''].map((h) => el('th', { text: h })))),
        el('tbody', {}, ...rows)),
      el('div', { class: 'row' }, el('button', { type: 'button', testid: 'exp-designs-close', text: 'Close', onclick: () => dialog.close() }))));
    dialog.addEventListener('click', (e) => { if (e.target === dialog) dialog.close(); });
    dialog.addEventListener('close', () => dialog.remove());
    document.body.append(dialog);
    dialog.showModal();
  }

  /// The list, as each poll of the monitor brings it.
  function render(list) {
    // "NAME started on this server" holds while it runs; once it has ended the list says how.
    const started = startedHere && list.find((e) => e.name === startedHere);
    if (started && started.state !== 'running') {
      startedHere = null;
      if ($('exp-plan').querySelector('[data-testid="exp-started"]')) $('exp-plan').replaceChildren();
    }
    $('experiment-list').replaceChildren(...list.map((e) => {
      const href = `/api/projects/${encodeURIComponent(project())}/experiments/${encodeURIComponent(e.name)}`;
      const c = e.current;
      const race = c && c.runs_used !== undefined
        ? ` · runs ${c.runs_used} / ${c.budget}${c.best_score !== undefined ? ` · best ${readable(c.best_score)}` : ''}` : '';
      const now = c && e.state !== 'finished'
        ? `${e.state === 'running' ? 'now' : 'next'}: ${c.mission} / ${c.condition} #${c.replicate} (${c.stage}${race})` : '';
      const buttons = [];
      if (e.state === 'running') buttons.push(el('button', { type: 'button', class: 'small', testid: `exp-stop-${e.name}`, text: 'Stop', onclick: () => act(e.name, 'stop') }));
      if (c && e.state !== 'finished' && c.stage === 'designing')
        buttons.push(el('button', { type: 'button', class: 'small', testid: `exp-follow-${e.name}`, text: 'Watch design',
          title: 'show the design it is making in the monitor (runs, elites, convergence, best)', onclick: () => onFollow(e.name) }));
      if (e.designs_done > 0)
        buttons.push(el('button', { type: 'button', class: 'small', testid: `exp-designs-${e.name}`, text: 'Designs…',
          title: 'open one of the designs it has made in the monitor (runs, elites, convergence, best)', onclick: () => chooseDesign(e.name) }));
      if (e.state === 'interrupted' || e.state === 'failed') buttons.push(el('button', { type: 'button', class: 'small', testid: `exp-resume-${e.name}`, text: 'Resume', onclick: () => act(e.name, 'resume') }));
      return el('li', { testid: `experiment-${e.name}`, class: 'experiment-row' },
        el('span', { class: 'design-actions' },
          el('strong', { text: e.name }),
          el('span', { testid: `exp-state-${e.name}`, text: `${e.state}${e.running_here ? ' (here)' : ''}` }),
          el('span', { class: 'spacer' }), ...buttons),
        el('span', { class: 'muted', testid: `exp-progress-${e.name}`, text: `${e.designs_done} / ${e.designs} designs done${now ? ` · ${now}` : ''}` }),
        el('span', { class: 'row' },
          el('a', { href: `${href}/report`, target: '_blank', rel: 'noopener', testid: `report-${e.name}`, text: 'report' }),
          el('a', { href: `${href}/report.json`, download: `${e.name}-report.json`, testid: `report-json-${e.name}`, text: 'report.json' }),
          el('a', { href: `${href}/designs.csv`, download: `${e.name}-designs.csv`, text: 'designs.csv' })));
    }));
    if (!list.length) $('experiment-list').append(el('li', { class: 'muted small', text: 'none yet: start one below, or with swarmdesign experiment' }));
  }

  $('exp-protocol').addEventListener('change', showMissions);
  $('exp-file').addEventListener('change', async () => {
    const file = $('exp-file').files[0];
    ownText = file ? await file.text() : null;
    if (file && !$('exp-name').value) $('exp-name').placeholder = file.name.replace(/\.json$/, '');
  });
  $('exp-dry').addEventListener('click', () => send(true));
  $('exp-form').addEventListener('submit', (e) => { e.preventDefault(); send(false); });
  api('/api/protocols', { quiet: true }).then((list) => {
    protocols = list;
    const labels = { validation: 'validation (each flavour alone)', combination: 'combination (flavours together)', architecture: 'architecture (FSM vs behaviour tree)' };
    $('exp-protocol').replaceChildren(...list.map((p) => el('option', { value: p.name, text: labels[p.name] || p.name })),
      el('option', { value: 'own', text: 'your own protocol file…' }));
    showMissions();
  }).catch(() => {});

  return { render };
}
