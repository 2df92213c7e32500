// Norm_Q of one edge distance (4.2.5) for Q = 0 or Q = 2^k: inside when
// D > -Q (D >= 0 for Q = 0); in the fringe n = (D + Q) shifted onto NF
// fraction bits, truncating; 1.0 = 2^NF for D >= 0.
module dda_norm #(
    parameter int W = girtd_pkg::D_W,
    parameter int FRAC = girtd_pkg::D_FRAC,
    parameter int NF = girtd_pkg::NORM_FRAC
) (
    input  logic signed [W-1:0] d_i,
    input  logic                q_zero_i,
    input  logic signed [girtd_pkg::Q_K_W-1:0] q_k_i,  // Q = 2^k, k = -4..3
    output logic                inside_o,
    output logic [NF:0]         n_o
);
  logic signed [W:0] q_raw, sum;
  // Shift amounts, signed, wide enough for FRAC + k with any D format.
  localparam int SHW = $clog2(FRAC + (1 << (girtd_pkg::Q_K_W - 1))) + 2;
  logic signed [SHW-1:0] q_shift;  // FRAC + k: Q as a raw D value is 1 << q_shift
  logic signed [SHW-1:0] shift;    // FRAC + k - NF

  assign q_shift = SHW'(FRAC) + SHW'(q_k_i);
  assign q_raw = (W + 1)'(1) << q_shift;
  assign sum = {d_i[W-1], d_i} + q_raw;
  assign shift = SHW'(FRAC - NF) + SHW'(q_k_i);

  always_comb begin
    inside_o = q_zero_i ? !d_i[W-1] : (!sum[W] && sum != '0);
    if (!d_i[W-1]) n_o = (NF + 1)'(1) << NF;
    else if (!inside_o) n_o = '0;
    else if (shift >= 0) n_o = (NF + 1)'(sum >>> shift);
    else n_o = (NF + 1)'(sum <<< (-shift));
  end
endmodule
