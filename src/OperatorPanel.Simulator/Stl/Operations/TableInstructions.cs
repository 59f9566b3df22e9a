using OperatorPanel.Simulator.Stl.Execution;
using static OperatorPanel.Simulator.Stl.Operations.StatusBits;

namespace OperatorPanel.Simulator.Stl.Operations;

/// <summary>
/// Table instructions (A5E00307987-04 chapter 6, "Table Instructions"; C79000-G7076-C233-01 p. 9-109, Figure 9-36 for
/// LIFO). ATT, FIFO and LIFO tables start with TL (maximum entries, at most 100) and EC (entry count), then the
/// entries; FND's table starts with EC. ATT on a full table sets SM1.4, FIFO/LIFO on an empty one SM1.5, both with
/// ENO = 0 and nothing moved. FND=/&lt;&gt;/&lt;/&gt; SRC, PATRN, INDX searches from entry INDX and leaves INDX at
/// the first match, or at EC when none matches. FILL IN, OUT, N writes IN into N words from OUT.
/// </summary>
internal static class TableInstructions
{
    /// <summary>ATT DATA, TBL.</summary>
    public static void Add(StlMachine m, StlOp op)
    {
        if (!m.TrySpan(op.B!, 2, out var area, out var offset))
        {
            return;
        }

        var limit = (short)StlMachine.ReadBytes(area, offset, 2);
        var count = (short)StlMachine.ReadBytes(area, offset + 2, 2);
        var full = count >= limit;
        if (!full && m.TrySpan(op.B!, 4 + ((count + 1) * 2), out _, out _))
        {
            StlMachine.WriteBytes(area, offset + 4 + (count * 2), 2, m.Read(op.A!, 2));
            StlMachine.WriteBytes(area, offset + 2, 2, (uint)(count + 1));
        }

        m.SetFlags(TableFull, full ? TableFull : (byte)0);
        m.Eno = !full;
    }

    /// <summary>FIFO TBL, DATA: the oldest entry; the rest move up.</summary>
    public static void First(StlMachine m, StlOp op) => Take(m, op, first: true);

    /// <summary>LIFO TBL, DATA: the newest entry.</summary>
    public static void Last(StlMachine m, StlOp op) => Take(m, op, first: false);

    /// <summary>FND=, FND&lt;&gt;, FND&lt;, FND&gt; SRC, PATRN, INDX (the relation in op.N: 0 =, 1 &lt;&gt;, 2 &lt;, 3 &gt;).</summary>
    public static void Find(StlMachine m, StlOp op)
    {
        if (!m.TrySpan(op.A!, 2, out var area, out var offset))
        {
            return;
        }

        var count = (short)StlMachine.ReadBytes(area, offset, 2);
        var pattern = (short)m.Read(op.B!, 2);
        for (var index = Math.Max((short)0, (short)m.Read(op.C!, 2)); index < count && m.TrySpan(op.A!, 4 + (index * 2), out _, out _); index++)
        {
            var entry = (short)StlMachine.ReadBytes(area, offset + 2 + (index * 2), 2);
            if (op.N switch { 0 => entry == pattern, 1 => entry != pattern, 2 => entry < pattern, _ => entry > pattern })
            {
                m.Write(op.C!, 2, (ushort)index);
                return;
            }
        }

        m.Write(op.C!, 2, (ushort)Math.Max((short)0, count));
    }

    /// <summary>FILL IN, OUT, N.</summary>
    public static void Fill(StlMachine m, StlOp op)
    {
        var words = (int)m.Read(op.C!, 1);
        if (m.TrySpan(op.B!, words * 2, out var area, out var offset))
        {
            var value = m.Read(op.A!, 2);
            for (var i = 0; i < words; i++)
            {
                StlMachine.WriteBytes(area, offset + (i * 2), 2, value);
            }
        }
    }

    private static void Take(StlMachine m, StlOp op, bool first)
    {
        if (!m.TrySpan(op.A!, 4, out var area, out var offset))
        {
            return;
        }

        var count = (short)StlMachine.ReadBytes(area, offset + 2, 2);
        var empty = count <= 0;
        if (!empty && m.TrySpan(op.A!, 4 + (count * 2), out _, out _))
        {
            var entries = offset + 4;
            m.Write(op.B!, 2, StlMachine.ReadBytes(area, first ? entries : entries + ((count - 1) * 2), 2));
            if (first)
            {
                Array.Copy(area, entries + 2, area, entries, (count - 1) * 2);
            }

            StlMachine.WriteBytes(area, offset + 2, 2, (uint)(count - 1));
        }

        m.SetFlags(TableEmpty, empty ? TableEmpty : (byte)0);
        m.Eno = !empty;
    }
}
