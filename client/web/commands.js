// The current parameters as text to paste elsewhere: JSON, a curl command
// and a `toon render` command that render the same image.
import { isPlainObject } from './params.js';

function shellQuote(text) {
  return /^[A-Za-z0-9_./:=@%+,-]+$/.test(text) ? text : `'${text.replace(/'/g, `'\\''`)}'`;
}

export function paramsJson(params) {
  return JSON.stringify(params, null, 2);
}

export function curlCommand(origin, params) {
  return `curl -X POST ${origin}/render -H 'Content-Type: application/json' \\\n  -d ${shellQuote(JSON.stringify(params))} -o render.png`;
}

// toon's --set takes key.sub=value with a JSON value (a plain word for a
// name); objects become dotted keys, arrays are given whole.
function setArguments(value, key, out) {
  if (isPlainObject(value)) {
    for (const [k, v] of Object.entries(value)) setArguments(v, key ? `${key}.${k}` : k, out);
  } else {
    const text = typeof value === 'string' ? value : JSON.stringify(value);
    out.push(`--set ${shellQuote(`${key}=${text}`)}`);
  }
  return out;
}

export function toonCommand(origin, params) {
  const { model, ...rest } = params;
  const words = ['toon', 'render'];
  if (origin !== 'http://127.0.0.1:8080') words.push('--server', origin);
  if (model) words.push('--model', model);
  words.push(...setArguments(rest, '', []), '-o', 'render.png');
  return words.join(' ');
}
