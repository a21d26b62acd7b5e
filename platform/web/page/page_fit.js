// How the page's canvas fills its space (docs/web.md): the canvas scaled to #stage keeping the
// world's aspect, and the size a run is given when the address names none.
'use strict';
window.noneuclidFit = {
  // The canvas's CSS size: as large as the stage allows, its pixels' aspect kept.
  fit(canvas, stage) {
    const scale = Math.min(stage.clientWidth / canvas.width, stage.clientHeight / canvas.height);
    if (!(scale > 0)) return;
    canvas.style.width = Math.floor(canvas.width * scale) + 'px';
    canvas.style.height = Math.floor(canvas.height * scale) + 'px';
  },
  // The run's size when the address gives none: the world's 5:3 as large as the stage allows, in
  // the screen's own pixels (CSS pixels times devicePixelRatio, so that a high-density screen
  // shows it sharp; at most 1600 wide), and the HUD's scale that makes its 8-pixel text at least
  // 9 CSS pixels tall.
  pageSize(stage) {
    const css = Math.max(240, Math.min(stage.clientWidth, stage.clientHeight * 5 / 3));
    const width = Math.max(240, Math.min(1600, Math.floor(css * (window.devicePixelRatio || 1) / 10) * 10));
    return {width, height: width * 3 / 5, hudScale: Math.max(1, Math.min(8, Math.ceil(9 * width / (8 * css))))};
  },
};
