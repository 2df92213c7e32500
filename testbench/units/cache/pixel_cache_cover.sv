// Cover points of hw/cache/pixel_cache for its unit bench
// (testbench/units/README.md), bound into the unit: hits, the two kinds of
// miss, and a page replaced or flushed with and without writes in it.
module pixel_cache_cover (
    input logic clk_i,
    input logic rst_ni,
    input logic [girtd_pkg::PAGE_NUMBER_W-1:0] head_page_i,
    input logic [girtd_pkg::PAGE_NUMBER_W-1:0] pix_page_i,
    input logic head_hit_o,
    input logic head_slot_valid_o,
    input logic head_slot_dirty_o,
    input logic flush_valid_o,
    input logic flush_dirty_o,
    input logic load_i,
    input logic write_i,
    input logic invalidate_i
);
  cover property (@(posedge clk_i) rst_ni && head_hit_o);                                   // a page hit
  cover property (@(posedge clk_i) rst_ni && !head_slot_valid_o);                           // a miss on an empty slot
  cover property (@(posedge clk_i) rst_ni && head_slot_valid_o && !head_hit_o);             // a miss on another page's slot
  cover property (@(posedge clk_i) rst_ni && load_i && head_slot_valid_o && head_slot_dirty_o);   // a written page replaced
  cover property (@(posedge clk_i) rst_ni && load_i && head_slot_valid_o && !head_slot_dirty_o);  // an unwritten one
  cover property (@(posedge clk_i) rst_ni && write_i && head_hit_o && head_page_i == pix_page_i);  // a pixel written, the next on its page
  cover property (@(posedge clk_i) rst_ni && invalidate_i && flush_valid_o && flush_dirty_o);   // a written page flushed
  cover property (@(posedge clk_i) rst_ni && invalidate_i && flush_valid_o && !flush_dirty_o);  // an unwritten one
  cover property (@(posedge clk_i) rst_ni && invalidate_i && load_i);                       // a flush beside a load
endmodule

bind pixel_cache pixel_cache_cover u_cover (.*);
