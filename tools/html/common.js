// What both plascap pages share: the status element that reports the page's state (for people, and
// for tests as data-* attributes), caught JavaScript errors, a failure message in place of the
// page, SI formatting and DOM building. Loaded before the page's own code.
(function () {
  'use strict';
  const status = document.getElementById('plascap-status');
  let errors = 0;

  function report(values) {
    for (const key of Object.keys(values)) status.dataset[key] = String(values[key]);
  }
  function countError(message) {
    errors += 1;
    report({ errors: errors, lastError: message });
  }
  window.addEventListener('error', function (e) { countError(e.message || String(e)); });
  window.addEventListener('unhandledrejection', function (e) { countError(String(e.reason)); });

  // Replaces the page by one message saying why it cannot be shown.
  function fail(message) {
    document.body.className = '';
    for (const el of Array.from(document.body.children)) {
      if (el !== status && el.tagName !== 'SCRIPT') el.remove();
    }
    status.className = 'error';
    status.textContent = message;
    report({ state: 'error', message: message });
  }

  function check(condition, message) {
    if (!condition) throw new Error(message);
  }

  // The page's data element, parsed and checked for its format and version.
  function readData(format, what) {
    const element = document.getElementById('plascap-data');
    check(element, 'the page holds no data (no element "plascap-data")');
    let d;
    try {
      d = JSON.parse(element.textContent);
    } catch (e) {
      throw new Error('its data is not valid JSON (' + e.message + ')');
    }
    check(d && d.format === format, 'its data is not ' + what + ' (format ' + JSON.stringify(d && d.format) + ')');
    check(d.version === 1, 'its data is version ' + JSON.stringify(d.version) + '; this page reads version 1');
    return d;
  }

  // Engineering notation with an SI prefix: 12.3 kN, 4.56 mJ; a power of the metre takes none
  // (5.38 mm² would be a millionth of it): 5.381e-3 m².
  function si(value, unit) {
    if (value === null || value === undefined) return '—';
    if (!isFinite(value)) return String(value) + ' ' + unit;
    if (/^m[²³⁴]/.test(unit)) return value.toExponential(3) + ' ' + unit;
    const prefixes = [[1e9, 'G'], [1e6, 'M'], [1e3, 'k'], [1, ''], [1e-3, 'm'], [1e-6, 'µ'], [1e-9, 'n']];
    const a = Math.abs(value);
    if (a === 0) return '0 ' + unit;
    for (const [f, p] of prefixes) {
      if (a >= f * 0.9995) return (value / f).toPrecision(3) + ' ' + p + unit;
    }
    return value.toExponential(2) + ' ' + unit;
  }

  function element(tag, attributes, parent) {
    const el = document.createElement(tag);
    for (const key of Object.keys(attributes || {})) {
      if (key === 'text') el.textContent = attributes[key];
      else el.setAttribute(key, attributes[key]);
    }
    if (parent) parent.appendChild(el);
    return el;
  }

  // Runs the page's builder; an exception it throws becomes the page's message.
  function run(what, build) {
    try {
      build();
    } catch (e) {
      countError(e.message);
      fail('This ' + what + ' cannot be shown: ' + e.message);
    }
  }

  window.plascapPage = {
    report: report, fail: fail, check: check, readData: readData, si: si, element: element, run: run,
    errors: function () { return errors; },
  };
})();
