// nontest: included by include.bas
prnt "from the library"
