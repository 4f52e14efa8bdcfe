// The web core draws text with the same pixels as native rb: every Latin-1 character of each of
// the 12 faces (Mono, Sans, Serif; regular, bold, italic, bold italic) at sizes from 6 to 72
// points, run by rb.run (build-web/site/rb.js, node) and by native `rb render`, compared pixel
// for pixel. The site's fonts are cut down to Latin-1 (scripts/web.sh), native rb's are whole.
// Usage: node fonts_test.js RB SITE WORK   (exit 77: no site)
'use strict';
const fs = require('fs'), path = require('path'), zlib = require('zlib'), {execFileSync} = require('child_process');
const [rbBin, site, work] = process.argv.slice(2);
if (!fs.existsSync(path.join(site, 'rb.js'))) {
  console.log(`skipped: no site at ${site} (scripts/web.sh builds it)`);
  process.exit(77);
}
const rb = require(path.resolve(site, 'rb.js'));
fs.mkdirSync(work, {recursive: true});

// RGB rows of a PNG as rb writes them (8-bit RGB or RGBA, or a palette of 1 to 8 bits: rb render's
// pictures of at most 256 colours), any filters.
function decodePng(buf) {
  let pos = 8, width = 0, height = 0, channels = 3, depth = 8, palette = null;
  const idat = [];
  while (pos < buf.length) {
    const size = buf.readUInt32BE(pos), type = buf.toString('latin1', pos + 4, pos + 8);
    const body = buf.subarray(pos + 8, pos + 8 + size);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0); height = body.readUInt32BE(4); depth = body[8];
      channels = {2: 3, 6: 4, 3: 1}[body[9]];
      if (!channels) throw new Error(`PNG colour type ${body[9]}`);
      if (body[12] !== 0 || !(depth === 8 || (body[9] === 3 && [1, 2, 4].includes(depth))))
        throw new Error(`unexpected PNG depth ${depth} or interlace`);
    } else if (type === 'PLTE') palette = body;
    else if (type === 'IDAT') idat.push(body);
    pos += 12 + size;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  // The filters work on whole bytes: `bpp` bytes back is the pixel to the left (1 for a palette).
  const stride = Math.ceil(width * channels * depth / 8), bpp = Math.max(1, channels * depth / 8);
  const out = Buffer.alloc(width * height * 3);
  let prev = Buffer.alloc(stride);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)], line = Buffer.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; i++) {
      const a = i >= bpp ? line[i - bpp] : 0, b = prev[i], c = i >= bpp ? prev[i - bpp] : 0;
      let p = 0;
      if (f === 1) p = a; else if (f === 2) p = b; else if (f === 3) p = (a + b) >> 1;
      else if (f === 4) { const q = a + b - c, pa = Math.abs(q - a), pb = Math.abs(q - b), pc = Math.abs(q - c); p = pa <= pb && pa <= pc ? a : pb <= pc ? b : c; }
      line[i] = (line[i] + p) & 255;
    }
    for (let x = 0; x < width; x++) {
      if (palette) {
        // Indices packed 8 / depth to a byte, the leftmost pixel in the high bits.
        const per = 8 / depth, index = (line[Math.floor(x / per)] >> ((per - 1 - x % per) * depth)) & ((1 << depth) - 1);
        for (let k = 0; k < 3; k++) out[(y * width + x) * 3 + k] = palette[index * 3 + k];
      } else {
        for (let k = 0; k < 3; k++) out[(y * width + x) * 3 + k] = line[x * channels + k];
      }
    }
    prev = line;
  }
  return {width, height, rgb: out};
}

function program(font, style, points) {
  const lines = [];
  let code = 32, y = 0;
  const px = Math.round(points * 96 / 72), perLine = Math.max(4, Math.floor(760 / px)), rowH = Math.ceil(px * 1.3);
  while (code < 256 && y + rowH < 600) {
    const n = Math.min(perLine, 256 - code);
    lines.push(`s = ""\nfor c = ${code} to ${code + n - 1}\n  s = s + char(c)\nnext\nxyText 4, ${y}, s, "${font}", ${points}, ${style}`);
    code += n; y += rowH;
  }
  return {text: lines.join('\n') + '\n', drawn: code - 32};
}

(async () => {
  const faces = ['Courier New', 'Arial', 'Times New Roman'];
  const styles = ['0', 'fs_Bold', 'fs_Italic', 'fs_Bold + fs_Italic'];
  const sizes = [6, 7, 8, 10, 12, 14, 18, 24, 36, 72];
  let compared = 0;
  for (const font of faces) for (const style of styles) for (const points of sizes) {
    const {text} = program(font, style, points);
    const file = path.join(work, 'text.bas'), png = path.join(work, 'text.png');
    fs.writeFileSync(file, text);
    execFileSync(rbBin, ['render', file, '-o', png], {stdio: ['ignore', 'ignore', 'inherit']});
    const want = decodePng(fs.readFileSync(png));
    const r = await rb.run(text, {seed: 1});
    if (r.error) throw new Error(`${font} ${style} ${points}: ${r.error}`);
    const got = decodePng(Buffer.from(r.png.split(',')[1], 'base64'));
    if (!got.rgb.equals(want.rgb)) {
      let i = 0;
      while (got.rgb[i] === want.rgb[i]) i++;
      const p = Math.floor(i / 3);
      throw new Error(`${font}, ${style}, ${points} points: the wasm core's pixels differ from rb render's, first at (${p % 800}, ${Math.floor(p / 800)})`);
    }
    compared++;
  }
  console.log(`fonts: ${compared} pictures equal to rb render's`);
})().catch((e) => { console.log('FAILED: ' + e.message); process.exit(1); });
