// Whether a parameter matters to the render, from the schema's own
// `x-applies-when` (described in the schema's $comment): the page hides a
// control whose conditions fail, since the renderer ignores that field then.
// Pure functions, no DOM.
import { getPointer, isPlainObject } from './params.js';

function deepEqual(a, b) {
  if (a === b) return true;
  if (typeof a !== typeof b || a === null || b === null || typeof a !== 'object') return false;
  if (Array.isArray(a) !== Array.isArray(b)) return false;
  const ka = Object.keys(a);
  const kb = Object.keys(b);
  return ka.length === kb.length && ka.every((k) => deepEqual(a[k], b[k]));
}

function typeMatches(value, type) {
  if (Array.isArray(type)) return type.some((t) => typeMatches(value, t));
  switch (type) {
    case 'array': return Array.isArray(value);
    case 'object': return isPlainObject(value);
    case 'null': return value === null;
    case 'integer': return Number.isInteger(value);
    case 'number': return typeof value === 'number';
    default: return typeof value === type;
  }
}

// The subset of JSON Schema the conditions use (the schema's $comment names
// it, and a unit test keeps the schema to it). As in JSON Schema, a keyword
// for another type (contains on a string) does not constrain the value.
export function satisfies(value, schema) {
  if (schema === true || schema === undefined) return true;
  if (schema === false) return false;
  if ('const' in schema && !deepEqual(value, schema.const)) return false;
  if (Array.isArray(schema.enum) && !schema.enum.some((v) => deepEqual(value, v))) return false;
  if (schema.type !== undefined && !typeMatches(value, schema.type)) return false;
  if (schema.not !== undefined && satisfies(value, schema.not)) return false;
  if (Array.isArray(schema.anyOf) && !schema.anyOf.some((s) => satisfies(value, s))) return false;
  if (Array.isArray(schema.allOf) && !schema.allOf.every((s) => satisfies(value, s))) return false;
  if (Array.isArray(value)) {
    if (schema.minItems !== undefined && value.length < schema.minItems) return false;
    if (schema.maxItems !== undefined && value.length > schema.maxItems) return false;
    if (schema.contains !== undefined && !value.some((v) => satisfies(v, schema.contains))) return false;
  }
  if (typeof value === 'string') {
    if (schema.minLength !== undefined && value.length < schema.minLength) return false;
    if (schema.maxLength !== undefined && value.length > schema.maxLength) return false;
  }
  if (isPlainObject(value) && isPlainObject(schema.properties)) {
    for (const [key, sub] of Object.entries(schema.properties)) {
      if (key in value && !satisfies(value[key], sub)) return false;
    }
  }
  return true;
}

// `conditions` is a property's x-applies-when, `pointer` the property's own
// JSON pointer, `effective` what the render will use. A key names a sibling
// of the property, or a field from the root when it starts with '/'.
export function applies(conditions, pointer, effective) {
  if (!isPlainObject(conditions)) return true;
  const parent = pointer.slice(0, pointer.lastIndexOf('/'));
  return Object.entries(conditions).every(([key, schema]) => {
    const at = key.startsWith('/') ? key : `${parent}/${key.replace(/~/g, '~0')}`;
    const value = getPointer(effective, at);
    return satisfies(value === undefined ? null : value, schema);
  });
}
