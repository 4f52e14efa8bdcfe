// Writes the site's service worker (web/sw.js with its file list and version) into the site:
//   node web/make_sw.js SITE_DIR
'use strict';
const fs = require('fs'), path = require('path'), crypto = require('crypto');
const site = process.argv[2];
const files = fs.readdirSync(site).filter((f) => f !== 'sw.js' && fs.statSync(path.join(site, f)).isFile()).sort();
const hash = crypto.createHash('sha256');
for (const f of files) hash.update(f + '\0').update(fs.readFileSync(path.join(site, f)));
const list = ['./', ...files.map((f) => './' + f)];
const text = fs.readFileSync(path.join(__dirname, 'sw.js'), 'utf8')
  .replace('@VERSION@', hash.digest('hex').slice(0, 16))
  .replace('@FILES@', JSON.stringify(list));
fs.writeFileSync(path.join(site, 'sw.js'), text);
