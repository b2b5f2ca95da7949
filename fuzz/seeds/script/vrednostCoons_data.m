% vrednostCoons_data.m -- AS PRINTED, bugs included (uses u and v without defining them; with a
% vector u, "u^2" is a matrix power and "[u;0;...]" a dimension mismatch).  A script.
%
% Source: Irena Čavdek, "Bézierove in Gordon-Coons krpe", zaključna naloga, UP FAMNIT, Koper 2014,
%         Priloga C (appendix C), "Vhod: primer zapisa krivulj za algoritem 6".
% Transcribed from the OCR'd thesis text, where the listing came out as one run-on paragraph
% ("$c1 = [u;0;u-u^2];$ c2 = [u;1;u]; $d1 = ...$"): the "$" math delimiters were removed and the
% line breaks restored, one statement per line, in the printed order.  No character of the
% statements themselves had to be reconstructed.
c1 = [u;0;u-u^2];
c2 = [u;1;u];
d1 = [0;v^2;v-v^2];
d2 = [1;v;v];
P1 = [0;0;0];
P2 = [1;0;0];
P3 = [0;1;0];
P4 = [1;1;1];
