-- Neovim with editors/neovim/rb.lua, headless (testdata/editors/CMakeLists.txt runs it):
--   nvim --headless -u NONE -i NONE --cmd 'filetype on' -c 'luafile THIS' -- RB_LUA PROGRAM RB_DIR
-- Opens PROGRAM as a user would, then checks that the file type is robotbasic, that rb lsp's
-- diagnostics arrive, and that hover and go to definition answer. Exits 0 when all hold, else 1
-- with what failed.
local rb_lua, program, rb_dir = unpack(vim.fn.argv())
local failures = {}
local function check(ok, what)
  if not ok then table.insert(failures, what) end
end

vim.env.PATH = rb_dir .. ':' .. vim.env.PATH
vim.cmd('luafile ' .. vim.fn.fnameescape(rb_lua))
vim.cmd('edit ' .. vim.fn.fnameescape(program))
local buf = vim.api.nvim_get_current_buf()
check(vim.bo[buf].filetype == 'robotbasic', 'filetype is ' .. vim.bo[buf].filetype .. ', not robotbasic')

-- Diagnostics: the misspelt command on line 3 (0-based 2).
local got = vim.wait(10000, function() return #vim.diagnostic.get(buf) > 0 end, 50)
check(got, 'no diagnostics within 10 s')
local found = false
for _, d in ipairs(vim.diagnostic.get(buf)) do
  if d.lnum == 2 and d.message:find('rForward', 1, true) then found = true end
end
check(found, 'no diagnostic on line 3 suggesting rForward')

local function request(method, line, col)
  local params = { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = line, character = col } }
  local answers = vim.lsp.buf_request_sync(buf, method, params, 5000) or {}
  for _, a in pairs(answers) do
    if a.result then return a.result end
  end
  return nil
end

-- Hover over rLocate (line 2): its usage line from the built-in table.
local hover = request('textDocument/hover', 1, 2)
local text = hover and hover.contents and (hover.contents.value or '') or ''
check(text:find('rLocate', 1, true) ~= nil, 'hover over rLocate: ' .. vim.inspect(hover))

-- Go to definition of the sub called on line 4 (0-based 3): its line 6, 0-based 5.
local def = request('textDocument/definition', 3, 6)
if def and def[1] then def = def[1] end
local line = def and (def.range or def.targetRange or {}).start
check(line and line.line == 5, 'definition of the sub: ' .. vim.inspect(def))

if #failures == 0 then
  io.stdout:write('neovim ' .. tostring(vim.version().major) .. '.' .. tostring(vim.version().minor) ..
                  ': filetype, diagnostics, hover and definition all work\n')
  vim.cmd('qall!')
else
  io.stdout:write(table.concat(failures, '\n') .. '\n')
  vim.cmd('cquit! 1')
end
