-- RobotBASIC in Neovim (0.9 or later) with rb's language server, `rb lsp`.
-- Copy this file to ~/.config/nvim/plugin/rb.lua (or paste it into init.lua). See docs/editors.md.

-- .bas files are RobotBASIC (Neovim would take them for another BASIC); highlight them with
-- Neovim's BASIC syntax, which knows the comments, strings and most keywords.
vim.filetype.add({ extension = { bas = 'robotbasic' } })

vim.api.nvim_create_autocmd('FileType', {
  pattern = 'robotbasic',
  callback = function(args)
    vim.bo[args.buf].syntax = 'basic'
    vim.bo[args.buf].commentstring = '// %s'
    local file = vim.api.nvim_buf_get_name(args.buf)
    local git = vim.fs.find({ '.git' }, { upward = true, path = vim.fs.dirname(file) })[1]
    vim.lsp.start({
      name = 'rb',
      cmd = { 'rb', 'lsp' },
      root_dir = git and vim.fs.dirname(git) or vim.fs.dirname(file),
    })
  end,
})

-- Run the current file in a terminal split: :RbRun
vim.api.nvim_create_user_command('RbRun', function()
  vim.cmd('write')
  vim.cmd('split | terminal rb run --tui ' .. vim.fn.shellescape(vim.api.nvim_buf_get_name(0)))
end, { desc = 'Run this RobotBASIC file with rb' })

-- With nvim-lspconfig instead of vim.lsp.start, the same server is:
--   local configs = require('lspconfig.configs')
--   if not configs.rb then
--     configs.rb = { default_config = { cmd = { 'rb', 'lsp' }, filetypes = { 'robotbasic' },
--                                       root_dir = require('lspconfig.util').find_git_ancestor,
--                                       single_file_support = true } }
--   end
--   require('lspconfig').rb.setup({})
