// Final transparency nf = n1 n2 n3 T (4.2.7). The U decoder routes a lone
// non-1 operand straight through; with two or more it cuts each to 1.P and
// multiplies pairwise through the PROM table, cutting each product back to
// 1.P before the next. Operands and nf are 1.NORM_FRAC (1.8: 256 = 1.0).
module dda_nf (
    input  logic [girtd_pkg::NF_W-1:0] n1_i,
    input  logic [girtd_pkg::NF_W-1:0] n2_i,
    input  logic [girtd_pkg::NF_W-1:0] n3_i,
    input  logic [girtd_pkg::NF_W-1:0] t_i,
    output logic [girtd_pkg::NF_W-1:0] nf_o
);
  localparam int P = girtd_pkg::PROM_FRAC;
  localparam int F = girtd_pkg::NORM_FRAC;  // the PROM's product is 0.F too
  localparam logic [F:0] ONE = (F + 1)'(1) << F;

`include "dda_prom_table.svh"

  logic [3:0] row;  // n1=1 n2=1 n3=1 T=1, as in the thesis' table
  logic [F:0] operands[4];
  logic [P-1:0] acc;
  logic [F-1:0] product;
  logic first;

  assign row = {n1_i == ONE, n2_i == ONE, n3_i == ONE, t_i == ONE};
  assign operands[0] = n1_i;
  assign operands[1] = n2_i;
  assign operands[2] = n3_i;
  assign operands[3] = t_i;

  always_comb begin
    acc = '0;
    product = '0;
    first = 1'b1;
    for (int i = 0; i < 4; i++) begin
      if (operands[i] != ONE) begin
        if (first) acc = operands[i][F-1:F-P];
        else begin
          product = prom_product(acc, operands[i][F-1:F-P]);
          acc = product[F-1:F-P];
        end
        first = 1'b0;
      end
    end
    unique case (row)
      4'd7:    nf_o = n1_i;
      4'd11:   nf_o = n2_i;
      4'd13:   nf_o = n3_i;
      4'd14:   nf_o = t_i;
      4'd15:   nf_o = ONE;
      default: nf_o = {1'b0, product};
    endcase
  end
endmodule
