-- RobotBASIC in Neovim with rb's language server, `rb lsp`. Works on Neovim 0.7 (Debian 12's
-- 0.7.2) and on 0.8, 0.9, 0.10 and later: where a newer API exists it is used, else its 0.7 form.
-- Copy this file to ~/.config/nvim/plugin/rb.lua (or paste it into init.lua). See docs/editors.md.

local rb_cmd = { 'rb', 'lsp' }

-- .bas files are RobotBASIC (Neovim would take them for another BASIC). A BufRead autocommand
-- rather than vim.filetype.add, which Neovim 0.7 does not consult unless told to.
vim.api.nvim_create_autocmd({ 'BufRead', 'BufNewFile' }, {
  pattern = '*.bas',
  callback = function(args)
    vim.bo[args.buf].filetype = 'robotbasic'
  end,
})

-- The project folder: the nearest folder above the file that holds .git, else the file's folder.
local function root_of(file)
  local dir = vim.fn.fnamemodify(file, ':p:h')
  local git = vim.fn.finddir('.git', dir .. ';')
  if git ~= '' then
    return vim.fn.fnamemodify(git, ':p:h:h')
  end
  return dir
end

local clients = {} -- Neovim 0.7: one client per project folder, attached to each of its buffers

vim.api.nvim_create_autocmd('FileType', {
  pattern = 'robotbasic',
  callback = function(args)
    -- Highlighted with Neovim's BASIC syntax, which knows the comments, strings and most keywords.
    vim.bo[args.buf].syntax = 'basic'
    vim.bo[args.buf].commentstring = '// %s'
    local root = root_of(vim.api.nvim_buf_get_name(args.buf))
    if vim.lsp.start then -- 0.8 and later
      vim.lsp.start({ name = 'rb', cmd = rb_cmd, root_dir = root }, { bufnr = args.buf })
      return
    end
    local id = clients[root]
    if not id or not vim.lsp.get_client_by_id(id) then
      id = vim.lsp.start_client({ name = 'rb', cmd = rb_cmd, root_dir = root })
      clients[root] = id
    end
    if id then
      vim.lsp.buf_attach_client(args.buf, id)
      -- Before 0.8 nothing sets these for a client started by hand.
      vim.bo[args.buf].omnifunc = 'v:lua.vim.lsp.omnifunc'
      vim.bo[args.buf].tagfunc = 'v:lua.vim.lsp.tagfunc'
    end
  end,
})

-- Run the current file in a terminal split: :RbRun
vim.api.nvim_create_user_command('RbRun', function()
  vim.cmd('write')
  vim.cmd('split | terminal rb run --tui ' .. vim.fn.shellescape(vim.api.nvim_buf_get_name(0)))
end, { desc = 'Run this RobotBASIC file with rb' })

-- With nvim-lspconfig instead, the same server is:
--   local configs = require('lspconfig.configs')
--   if not configs.rb then
--     configs.rb = { default_config = { cmd = { 'rb', 'lsp' }, filetypes = { 'robotbasic' },
--                                       root_dir = require('lspconfig.util').find_git_ancestor,
--                                       single_file_support = true } }
--   end
--   require('lspconfig').rb.setup({})
