% vrednostCoons.m -- AS PRINTED, bugs included (declares no output: the value is only displayed
% by the missing semicolon on line 5).  See ../fixed/vrednostCoons.m.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga C (appendix C), Algoritem 6: vrednostCoons.
%         Vhod: parametra u in v, štiri mejne krivulje ter njihova oglišča
%         Izhod: izračuna točko na Coonsovi krpi pri parametrih u in v
% Transcribed from the OCR'd thesis text: line numbers removed, indentation normalised.  No
% character had to be reconstructed.
function vrednostCoons(u,v,c1,c2,d1,d2,P1,P2,P3,P4)
rc = (1-v)*c1+v*c2;
rd = (1-u)*d1+u*d2;
rcd = (1-u)*(1-v)*P1+u*(1-v)*P2+(1-u)*v*P3+u*v*P4;
T = rc+rd-rcd
end;
