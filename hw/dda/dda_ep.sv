// One adder element processor (fig. 4.3, 4.22): value, d/dx, d/dy and AUX
// registers around one W-bit adder that wraps. Every EP performs the same
// operation each clock.
//
// The value register carries G guard bits above the hardware's W (the wrap
// detector, not part of the thesis' design): the low W bits are exactly the
// W-bit register's, and wrapped_o says they differ from the true sum (the
// W + G-bit one), the count report.json's `numerics` keeps.
module dda_ep #(
    parameter int W = girtd_pkg::COLOR_W,
    parameter int G = 0
) (
    input  logic                clk_i,
    // The load comes apart from the sequencer's operation: op_i depends on
    // registers only, so no adder's mux hangs on the DDA's input port (a
    // Verilated model evaluates logic fed by top inputs on every eval).
    input  logic                load_i,   // a parameter set is taken: value_i, dx_i, dy_i
    input  logic [girtd_pkg::OP_W-1:0] op_i,  // never OP_LOAD
    input  logic signed [W-1:0] value_i,
    input  logic signed [W-1:0] dx_i,
    input  logic signed [W-1:0] dy_i,
    output logic signed [W-1:0] value_o,
    output logic signed [W-1:0] dx_o,
    output logic                wrapped_o
);
  localparam int X = W + G;
  logic signed [X-1:0] value_q, value_d, aux_q;
  logic signed [W-1:0] dx_q, dy_q;

  always_comb begin
    value_d = value_q;
    unique case (op_i)
      girtd_pkg::OP_XINC:    value_d = value_q + X'(dx_q);
      girtd_pkg::OP_XDEC:    value_d = value_q - X'(dx_q);
      girtd_pkg::OP_YINC:    value_d = value_q + X'(dy_q);
      girtd_pkg::OP_RESTORE: value_d = aux_q;
      default:               value_d = value_q;
    endcase
  end

  always_ff @(posedge clk_i) begin
    value_q <= load_i ? X'(value_i) : value_d;
    if (load_i) begin
      dx_q <= dx_i;
      dy_q <= dy_i;
    end
    if (op_i == girtd_pkg::OP_SAVE) aux_q <= value_q;
  end

  assign value_o = value_q[W-1:0];
  assign dx_o = dx_q;
  assign wrapped_o = value_q[X-1:W-1] != {(G + 1){value_q[W-1]}};
endmodule
