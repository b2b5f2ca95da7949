% tenzor.m -- AS PRINTED.  See ../fixed/tenzor.m.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga B (appendix B), Algoritem 4: tenzor.
%         Vhod: kontrolne točke   Izhod: matriko B pretvori v tenzor
% Transcribed from the OCR'd thesis text: line numbers removed, indentation normalised.  No
% character had to be reconstructed.  The listing is printed without a closing "end" for the
% function (legal in an Octave function file); it is kept that way.
function A=tenzor(B)
m=size(B)(1)-1;
n=(size(B)(2)/3) -1;
for k=1: m+1
    for l=1: n+1
        A(k,l,:)= B(k,3*l-2:3*l);
    end;
end;
