// Screenshot: renders the view at once (the WebGL canvas keeps its drawing buffer), copies
// it to a 2D canvas, in false colour appends the legend on the right as `relight render`
// does, and downloads the result as PNG (canvas.toBlob + <a download>).
import { drawLegend } from './legend.js';
import { downloadBlob } from './ui.js';

export async function screenshot(viewer, labelsCanvas, filename) {
  viewer.renderNow();
  const src = viewer.canvas;
  const falseColour = viewer.used.mode !== 'tonemapped';
  const legendWidth = falseColour ? Math.round(110 * (src.height / 600)) + 60 : 0;
  const out = document.createElement('canvas');
  out.width = src.width + legendWidth;
  out.height = src.height;
  const ctx = out.getContext('2d');
  ctx.drawImage(src, 0, 0);
  if (labelsCanvas && labelsCanvas.width) ctx.drawImage(labelsCanvas, 0, 0, src.width, src.height);
  if (falseColour) drawLegend(ctx, src.width, legendWidth, src.height, viewer.used);
  const blob = await new Promise((resolve) => out.toBlob(resolve, 'image/png'));
  downloadBlob(blob, filename);
  return blob;
}
