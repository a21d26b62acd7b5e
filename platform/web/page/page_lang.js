// The page's words (docs/languages.md): the engine's catalogue (lang/texts.hpp, through
// nw_texts) in the language of the address's ?lang=, else of the browser's first language
// (English where noneuclid has none). page.js labels the page with them and passes the code to
// the engine as --lang, so that the HUD speaks it too. A bad ?lang= is the engine's to refuse,
// in its one sentence.
'use strict';
window.noneuclidLanguage = (() => {
  const $ = (id) => document.getElementById(id);
  const texts = {};  // name -> text; texts.lang: the code
  const t = (name) => texts[name] ?? name;
  // A text with printf-style %d and %s, filled in order.
  const fill = (name, ...values) => t(name).replace(/%[ds]/g, () => String(values.shift()));

  // Reads the catalogue from the engine `mod` and labels every element with a data-text; the
  // language menu reloads the page in the one chosen.
  function load(mod, params) {
    const want = params.get('lang') || navigator.language || 'en';
    const text = mod.UTF8ToString(mod.ccall('nw_texts', 'number', ['string'], [want]));
    for (const line of text.split('\n')) {
      const tab = line.indexOf('\t');
      if (tab > 0) texts[line.slice(0, tab)] = line.slice(tab + 1);
    }
    document.documentElement.lang = texts.lang;
    for (const e of document.querySelectorAll('[data-text]')) e.textContent = t(e.dataset.text);
    const choice = $('language');
    choice.value = texts.lang;
    choice.addEventListener('change', () => {
      const link = new URLSearchParams(location.search);
      link.set('lang', choice.value);
      location.search = '?' + link.toString();
    });
  }

  return {t, fill, load, code: () => texts.lang || 'en'};
})();
