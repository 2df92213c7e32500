// Cover points of hw/vram for its unit bench (testbench/units/README.md),
// bound into the unit: the operations' overlaps the port's arbitration decides.
module vram_cover (
    input logic       clk_i,
    input logic       rst_ni,
    input logic       clear_i,
    input logic       swap_i,
    input logic [girtd_pkg::LONG_TIME_W-1:0] ticks_i,
    input logic       busy_q,
    input logic       we_q,
    input logic       clearing_q,
    input logic       stealing_q,
    input logic       clear_pending_q,
    input logic       finishing,
    input logic       accepting,
    input logic       steal_due_q,
    input logic [7:0] steals_owed_q
);
  logic fetching, writing;
  assign fetching = busy_q && !we_q && !clearing_q && !stealing_q;
  assign writing = busy_q && we_q && !clearing_q && !stealing_q;
  cover property (@(posedge clk_i) rst_ni && accepting && !busy_q);                 // a request to an idle port
  cover property (@(posedge clk_i) rst_ni && accepting && finishing && writing);    // back to back after a write
  cover property (@(posedge clk_i) rst_ni && accepting && finishing && fetching);   // back to back after a fetch
  cover property (@(posedge clk_i) rst_ni && steal_due_q && fetching && !finishing);  // a stolen cycle due during a fetch
  cover property (@(posedge clk_i) rst_ni && steal_due_q && writing && !finishing);   // ... during a write
  cover property (@(posedge clk_i) rst_ni && steal_due_q && clear_pending_q);       // a steal and a clear both waiting
  cover property (@(posedge clk_i) rst_ni && clear_i && !busy_q);                   // a clear asked while idle
  cover property (@(posedge clk_i) rst_ni && clear_i && busy_q && !finishing);      // ... while busy: it waits
  cover property (@(posedge clk_i) rst_ni && accepting && finishing && clearing_q); // a fetch or write right after a clear
  cover property (@(posedge clk_i) rst_ni && steals_owed_q == 8'hFF);               // owed steals saturate
  cover property (@(posedge clk_i) rst_ni && swap_i && busy_q);                     // a swap during an operation
  cover property (@(posedge clk_i) rst_ni && busy_q && ticks_i > 1);                // a warped edge during an operation
  cover property (@(posedge clk_i) rst_ni && !busy_q && ticks_i > 1);               // ... while idle
endmodule

bind vram vram_cover u_cover (.*);
