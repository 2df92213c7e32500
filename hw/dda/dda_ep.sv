// One adder element processor (fig. 4.3, 4.22): value, d/dx, d/dy and AUX
// registers around one W-bit adder that wraps. Every EP performs the same
// operation each clock.
module dda_ep #(
    parameter int W = girtd_pkg::COLOR_W
) (
    input  logic                clk_i,
    input  logic [girtd_pkg::OP_W-1:0] op_i,
    input  logic signed [W-1:0] value_i,  // start value, taken on OP_LOAD
    input  logic signed [W-1:0] dx_i,
    input  logic signed [W-1:0] dy_i,
    output logic signed [W-1:0] value_o,
    output logic signed [W-1:0] dx_o
);
  logic signed [W-1:0] value_q, value_d, dx_q, dy_q, aux_q;

  always_comb begin
    value_d = value_q;
    unique case (op_i)
      girtd_pkg::OP_LOAD:    value_d = value_i;
      girtd_pkg::OP_XINC:    value_d = value_q + dx_q;
      girtd_pkg::OP_XDEC:    value_d = value_q - dx_q;
      girtd_pkg::OP_YINC:    value_d = value_q + dy_q;
      girtd_pkg::OP_RESTORE: value_d = aux_q;
      default:               value_d = value_q;
    endcase
  end

  always_ff @(posedge clk_i) begin
    value_q <= value_d;
    if (op_i == girtd_pkg::OP_LOAD) begin
      dx_q <= dx_i;
      dy_q <= dy_i;
    end
    if (op_i == girtd_pkg::OP_SAVE) aux_q <= value_q;
  end

  assign value_o = value_q;
  assign dx_o = dx_q;
endmodule
