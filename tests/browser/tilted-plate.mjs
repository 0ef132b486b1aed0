// A Code V sequence file of our own: an N-BK7 plate tilted 10 degrees about x (returning decentres,
// DAR) before an N-BK7 singlet, R 50 / -50, 5 mm; EPD 10, fields 0 and 3 degrees.
export const TILTED_PLATE_SEQ = `RDM
LEN "A plate tilted 10 degrees before a singlet"
DIM M
WL 587.5618
EPD 10
YAN 0 3
SO 0 1e10
S 0 4 N-BK7_SCHOTT
  DAR
  ADE 10
S 0 5
  DAR
  ADE 10
S 50 5 N-BK7_SCHOTT
STO
S -50 45
SI 0 0
GO
`;
