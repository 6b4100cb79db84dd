// SPDX-License-Identifier: MIT
// The failure timeline in words: events.csv, one row per moment and kind of event (elements that
// fail together, like the two mirror posts of a centred impact, share a row).
import { pair, fmt, seconds } from './units.js';

// What each event type means and how its value (SI) reads.
const KINDS = {
  post_hinge: { group: 'yield', text: (who) => `${who} yield${s(who)}: a plastic hinge forms at the base`, value: (v) => `moment capacity ${pair('moment', v)}` },
  footing_rotation: { group: 'yield', text: (who) => `${who} start${s(who)} rotating in the soil (footing at its capacity)`, value: (v) => `moment capacity ${pair('moment', v)}` },
  post_rotation_limit: { group: 'fail', text: (who) => `${who} fail${s(who)}: struck and pushed over until the vehicle rides over it (its top down to the pushing edge, or past its rotation limit), it leaves the barrier`, value: (v) => `tilt ${fmt((v * 180) / Math.PI, 1)}°` },
  post_down: { group: 'fail', text: (who) => `${who} ${/ and /.test(who) ? 'are' : 'is'} down: folded over to the ground, still holding the cables threaded or clamped on ${/ and /.test(who) ? 'them' : 'it'}`, value: (v) => `tilt ${fmt((v * 180) / Math.PI, 1)}°` },
  post_shear: { group: 'fail', text: (who) => `${who} fail${s(who)}: sheared off at the base`, value: (v) => `base shear ${pair('force', v)}` },
  post_withdrawal: { group: 'yield', text: (who) => `${who} start${s(who)} sliding out of the footing (pull out of it at its pullout capacity)`, value: (v) => `axial pull ${pair('force', v)}` },
  post_pullout: { group: 'fail', text: (who) => `${who} fail${s(who)}: slid all the way out of the footing`, value: (v) => `axial pull ${pair('force', v)}` },
  anchor_yield: { group: 'yield', text: (who) => `${who} start${s(who)} sliding through the soil (footing at its capacity)`, value: (v) => `capacity ${pair('force', v)}` },
  anchor_withdrawal: { group: 'yield', text: (who) => `${who} start${s(who)} rising out of the ground (the cables' uplift at its pullout capacity)`, value: (v) => `uplift ${pair('force', v)}` },
  anchor_pullout: { group: 'fail', text: (who) => `${who} ${/ and /.test(who) ? 'have' : 'has'} risen all the way out of the ground: its cables are released`, value: (v) => `uplift ${pair('force', v)}` },
  cable_break: { group: 'break', text: (who, end, cable, post) => `${who} break${s(who)}${post === undefined ? '' : ` at post ${post}'s hole`}`, value: (v) => `tension ${pair('force', v)}` },
  termination_break: { group: 'break', text: (who, end) => `${who} break${s(who)} at the end fitting on the ${end === 0 ? 'start' : 'end'} anchor`, value: (v) => `end span tension ${pair('force', v)}` },
  termination_slip: { group: 'slip', text: (who, end) => `${who} start${s(who)} slipping through the end fitting on the ${end === 0 ? 'start' : 'end'} anchor`, value: (v) => `end span tension ${pair('force', v)}` },
  cable_release: { group: 'slip', text: (who, end, cable) => `${who} let${s(who)} ${cable === undefined ? 'a cable' : `cable ${cable}`} go: bent over, its slot, hook or fitting no longer holds it`, value: (v) => `pull along the post ${pair('force', v)}` },
  termination_at_post: { group: 'slip', text: (who, end, cable) => `${who} let${s(who)} ${cable === undefined ? 'a cable' : `cable ${cable}`} run straight on to the ${end === 0 ? 'start' : 'end'} anchor: the rope's end has reached ${/ and /.test(who) ? 'their holes' : 'its hole'}`, value: (v) => `anchor moved ${pair('length', v)}` },
  cable_pulled_off: { group: 'slip', text: (who, end, cable) => `${who} let${s(who)} ${cable === undefined ? 'a cable' : `cable ${cable}`} go: its keyway bolt or bracket pulled off the post's face`, value: (v) => `pull off the face ${pair('force', v)}` },
  cable_struck_off: { group: 'slip', text: (who, end, cable) => `${who} let${s(who)} ${cable === undefined ? 'a cable' : `cable ${cable}`} go: struck by the vehicle, it leaves the cable's path`, value: (v) => `pull on the post ${pair('force', v)}` },
  override: { group: 'slip', text: (who) => `The vehicle rides over ${lower(who)}: it slips under the front face and stops holding the vehicle`, value: () => '' },
  underride: { group: 'slip', text: (who) => `The vehicle runs under ${lower(who)}: it slips over the front face and stops holding the vehicle`, value: () => '' },
  stopped: { group: 'end', text: () => 'The vehicle has stopped: the barrier contained it', value: (v) => `dynamic penetration ${pair('length', v)}` },
  breakthrough: { group: 'end', text: () => 'The vehicle is through the barrier: no cable holds it any more', value: (v) => `exit speed ${pair('speed', v)}` },
  // the run's end, a vehicle's length after the loss of contact (exit_time_s), when the vehicle left
  redirected: { group: 'end', text: (who, end, cable, post, s) => `The run ends: the vehicle left the barrier on the traffic side at t = ${seconds(s.exit_time_s)} and has gone its own length since; the barrier redirected it`, value: (v) => `exit speed ${pair('speed', v)}` },
};

function s(who) {
  return / and /.test(who) ? '' : 's';
}
function lower(who) {
  return who.charAt(0).toLowerCase() + who.slice(1);
}

function list(words) {
  return words.length <= 1 ? words.join('') : `${words.slice(0, -1).join(', ')} and ${words[words.length - 1]}`;
}

// Who: "Post 7 (x = 19.51 m)", "Posts 7 and 8 (x = 19.51 and 21.95 m)", "Cable 1 (1.22 m high)".
function who(data, kind, elements) {
  const b = data.barrier;
  if (kind === 'post') {
    const xs = elements.map((p) => (b.posts[p] ? fmt(b.posts[p][0], 2) : '?'));
    return `${elements.length > 1 ? 'Posts' : 'Post'} ${list(elements.map(String))} (x = ${list(xs)} m)`;
  }
  if (kind === 'cable') {
    const hs = elements.map((c) => (b.cables[c] ? fmt(b.cables[c][0], 2) : '?'));
    return `${elements.length > 1 ? 'Cables' : 'Cable'} ${list(elements.map(String))} (${list(hs)} m high)`;
  }
  if (kind === 'anchor') return list(elements.map((a) => (a === 0 ? 'The start anchor' : 'The end anchor')));
  return 'The vehicle';
}

export const GROUP_COLORS = { yield: '#9933bf', fail: '#1a1a1a', break: '#d62728', slip: '#e67300', end: '#1f77b4', contact: '#2ca02c' };

// Rows: {t, type, group, text, value, elements, kind}. The first contact comes first.
export function timeline(data) {
  const rows = [];
  if (data.summary.first_contact_time_s !== null) {
    rows.push({ t: data.summary.first_contact_time_s, type: 'contact', group: 'contact', kind: 'vehicle', elements: [], text: 'First contact: the front face reaches the cables', value: '' });
  }
  // a termination event's sixth item: its cable end, 0 at the start anchor, 1 at the end anchor (-1 for
  // none); a cable_release's, cable_pulled_off's, cable_struck_off's or termination_at_post's seventh: the cable its post let go (-1 for none); a cable_break's eighth: the
  // post at whose hole the rope broke (the terminal's "at post N's hole")
  for (const [t, type, kind, element, value, end, cable, post] of data.events) {
    const last = rows[rows.length - 1];
    if (last && last.t === t && last.type === type && last.kind === kind && last.end === end && last.cable === cable && last.post === post && kind !== 'vehicle') {
      last.elements.push(element);
      last.values.push(value);
      continue;
    }
    rows.push({ t, type, kind, end, cable, post, group: KINDS[type] ? KINDS[type].group : 'end', elements: [element], values: [value] });
  }
  for (const r of rows) {
    if (r.type === 'contact') continue;
    const k = KINDS[r.type];
    const w = who(data, r.kind, r.elements);
    r.text = k ? k.text(w, r.end, r.cable, r.post, data.summary) : `${r.type}: ${w}`;
    const distinct = [...new Set(r.values.map((v) => v.toPrecision(4)))];
    r.value = k ? (distinct.length === 1 ? k.value(r.values[0]) : r.values.map((v) => k.value(v)).join('; ')) : '';
  }
  // a run that ends at its time limit has no end event: say so
  if (data.summary.outcome === 'time_limit') {
    const speed = data.series.speed[data.series.speed.length - 1];
    rows.push({ t: data.summary.t_end_s, type: 'time_limit', group: 'end', kind: 'vehicle', elements: [], text: `The simulated time ends${data.summary.first_contact_time_s === null ? ': the vehicle never reached the barrier' : ''}`, value: `speed then ${pair('speed', speed)}` });
  }
  return rows;
}
