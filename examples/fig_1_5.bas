rLocate 400,300  
rForward 120  
rTurn 90
