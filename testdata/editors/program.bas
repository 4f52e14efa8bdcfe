// nontest: the program Neovim opens in nvim_test.lua (a misspelt command on line 3)
rLocate 400, 300
rForwrd 20
call square
end
sub square
  rTurn 90
return
