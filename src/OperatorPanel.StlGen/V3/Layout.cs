using System.Globalization;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.StlGen.V3;

/// <summary>
/// Where the v3 handler keeps its bytes (docs/protocol.md section 6, "The handler's V bytes"), all inside Core's
/// <see cref="HandlerShape.VBytes"/> from V_FIRST on: the request buffer R (byte 0 = RCV/XMT count), the work bytes,
/// and in the full handler the list's work bytes, the copy C (every slot's 4-byte window) and the slots (destination
/// pointer in R, source pointer, length).
/// </summary>
internal sealed class Layout
{
    /// <summary>FLAGS bit: the transmitter is owned (a chunk is on the wire).</summary>
    public const int Owned = 0;


    /// <summary>FLAGS bit: the reply to STOP is out; OP_PANEL executes STOP.</summary>
    public const int StopNow = 2;

    /// <summary>FLAGS bit: the copy holds what the last list reply reported (not after DEFINE LIST or 07).</summary>
    public const int CopyValid = 3;

    /// <summary>FLAGS bit: a window differed from its copy in this READ LIST (a group went through phase Changes).</summary>
    public const int Differs = 4;

    /// <summary>FLAGS bit: SM0.7 as the last scan saw it (the mode switch's edges).</summary>
    public const int RunSeen = 7;

    public Layout(int vFirst, HandlerShape shape)
    {
        (First, Shape) = (vFirst, shape);
        Work = 1 + shape.RequestBytes;
        ListWork = Work + HandlerShape.WorkBytes;
        C = ListWork + HandlerShape.ListWorkBytes;
        Slots = C + shape.CopyBytes;
        var end = shape.HasList ? Slots + (HandlerShape.SlotBytes * shape.ListItems) : ListWork;
        if (end != shape.VBytes)
        {
            throw new InvalidOperationException($"layout ends at {end}, Core's V_BYTES is {shape.VBytes}");
        }
    }

    public int First { get; }

    public HandlerShape Shape { get; }

    public int LastByte => First + Shape.VBytes - 1;

    /// <summary>Offsets from V_FIRST: the work bytes (<see cref="HandlerShape.WorkBytes"/>).</summary>
    public int Work { get; }

    /// <summary>STEP: a word, one bit per <see cref="Phase"/> (the check's two bits together for the reply's); 0 = no request.</summary>
    public int Step => Work;

    public int Flags => Work + 2;

    public int Cmd => Work + 3;

    /// <summary>STATUS of the reply; phase Changes counts INDEX in it.</summary>
    public int Status => Work + 4;

    /// <summary>The check's XOR sum A (a double word, folded to 16 bits at the end) and Horner sum B.</summary>
    public int SumA => Work + 5;

    public int SumB => Work + 9;

    /// <summary>The finished check: A's low word (the A field once folded) then B, a double word.</summary>
    public int Check => SumA + 2;

    /// <summary>The request's check as received; its last word is REQCHECK.</summary>
    public int Rx => Work + 11;

    /// <summary>A loop's pointer between scans, and where it ends (the check's place, a quarter's end).</summary>
    public int Walk => Work + 15;

    public int End => Work + 19;

    /// <summary>Pointers: the last reply byte ready to send, the last handed to XMT (its count byte); LAST a pointer for CHANGES and DEFINE LIST.</summary>
    public int Covered => Work + 23;

    public int Sent => Work + 27;

    public int Last => Work + 31;

    /// <summary>P, the payload length (word); then an item's length (word, its low byte BMB's count).</summary>
    public int Temp => Work + 35;

    /// <summary>The quarter phase Compare goes on from.</summary>
    public int Count => Work + 39;

    /// <summary>The STEP word's value for <paramref name="phase"/>.</summary>
    public static int StepValue(Phase phase) => phase == Phase.Check ? 1 : 1 << (int)phase;

    /// <summary>STEP's value in the reply's check: the check's bit and the reply's.</summary>
    public static int ReplyCheckValue => StepValue(Phase.Check) | StepValue(Phase.ReplyFlag);

    /// <summary>"MOVW the reply's check, STEP".</summary>
    public (string, string[]) GoReplyCheck() => ("MOVW", [ReplyCheckValue.ToString(CultureInfo.InvariantCulture), W(Step)]);

    /// <summary>"MOVW 0, STEP": the request is done.</summary>
    public (string, string[]) Done() => ("MOVW", ["0", W(Step)]);

    /// <summary>"MOVW phase, STEP".</summary>
    public (string, string[]) Go(Phase phase) => ("MOVW", [StepValue(phase).ToString(CultureInfo.InvariantCulture), W(Step)]);

    /// <summary>STEP's bit for <paramref name="phase"/> (a word is high byte first: bits 8-15 in its first byte).</summary>
    public string PhaseBit(Phase phase) => Bit(Step + ((int)phase < 8 ? 1 : 0), (int)phase % 8);

    /// <summary>The list's work bytes (<see cref="HandlerShape.ListWorkBytes"/>).</summary>
    public int ListWork { get; }

    /// <summary>N: the slots of the list; 0 = no list.</summary>
    public int N => ListWork;

    /// <summary>D: the list data bytes.</summary>
    public int D => ListWork + 1;

    /// <summary>USED: bit g set when group g (slots 8g to 8g + 7) is in the list.</summary>
    public int Used => ListWork + 2;

    /// <summary>The group the gather is at: one bit (group g = bit g).</summary>
    public int Group => ListWork + 3;

    /// <summary>TAIL: a pointer to R byte 6 + D, where a whole list's data ends (also the limit of CHANGES entries).</summary>
    public int Tail => ListWork + 4;

    /// <summary>A pointer to the slot DEFINE LIST stores next.</summary>
    public int NextSlot => ListWork + 8;

    /// <summary>The copy: slot k's window at C + 4k, as the last READ LIST reported it.</summary>
    public int C { get; }

    /// <summary>Slot k at Slots + 9k: its destination pointer (in R), its source pointer, its length.</summary>
    public int Slots { get; }

    public int Slot(int k) => Slots + (HandlerShape.SlotBytes * k);

    public string B(int offset) => "VB" + Abs(offset);

    public string W(int offset) => "VW" + Abs(offset);

    public string Dw(int offset) => "VD" + Abs(offset);

    public string Bit(int offset, int bit) => $"V{Abs(offset)}.{bit.ToString(CultureInfo.InvariantCulture)}";

    public string Ptr(int offset) => "&VB" + Abs(offset);

    public string FlagBit(int bit) => Bit(Flags, bit);

    private string Abs(int offset) => (First + offset).ToString(CultureInfo.InvariantCulture);
}
