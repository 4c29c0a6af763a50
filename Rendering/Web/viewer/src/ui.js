// The page's controls: plain DOM elements with stable ids (the browser test finds them).

export function el(tag, props = {}, children = []) {
  const node = document.createElement(tag);
  Object.assign(node, props);
  (Array.isArray(children) ? children : [children]).forEach((child) => {
    node.appendChild(typeof child === 'string' ? document.createTextNode(child) : child);
  });
  return node;
}

// A number with `digits` significant digits, without trailing noise.
export function format(value, digits = 4) {
  if (value === undefined || value === null || Number.isNaN(value)) return 'n/a';
  if (!Number.isFinite(value)) return String(value);
  return Number(value.toPrecision(digits)).toString();
}

export function fieldset(parent, title, id) {
  const box = el('fieldset', { id: `${id}-controls` }, [el('legend', {}, title)]);
  parent.appendChild(box);
  return box;
}

export function checkbox(parent, id, text, checked, onChange) {
  const input = el('input', { type: 'checkbox', id, checked });
  input.addEventListener('change', () => onChange(input.checked));
  parent.appendChild(el('label', { htmlFor: id }, [input, ` ${text}`]));
  return input;
}

// A slider with its value shown beside its label; onInput(value) on every move.
export function slider(parent, id, text, min, max, step, value, onInput) {
  const shown = el('span', { id: `${id}-value` }, format(value));
  const input = el('input', { type: 'range', id, min: String(min), max: String(max), step: String(step), value: String(value) });
  input.value = String(value);
  input.addEventListener('input', () => {
    shown.textContent = format(Number(input.value));
    onInput(Number(input.value));
  });
  parent.appendChild(el('label', { htmlFor: id }, [`${text}: `, shown]));
  parent.appendChild(input);
  return input;
}

const css = (rgb) => `rgb(${rgb.map((c) => Math.round(255 * c)).join(',')})`;

// A colour ramp with its two ends' values.
export function ramp(id, stops, lo, hi, loText, hiText) {
  const bar = el('div', { className: 'ramp' });
  bar.style.background = `linear-gradient(to right, ${stops.map(css).join(', ')})`;
  return el('div', { id }, [bar, el('div', { className: 'ends' }, [
    el('span', {}, `${format(lo)} ${loText}`.trim()), el('span', {}, `${format(hi)} ${hiText}`.trim())])]);
}

// Rows of a colour swatch and a text.
export function legendRows(id, rows) {
  return el('div', { id }, rows.map(([rgb, text]) => {
    const swatch = el('span', { className: 'swatch' });
    swatch.style.background = css(rgb);
    return el('div', {}, [swatch, text]);
  }));
}
