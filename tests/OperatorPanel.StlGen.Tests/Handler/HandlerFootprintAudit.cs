using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Transport;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Checks;
using OperatorPanel.StlGen.Handler;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Handler;

/// <summary>
/// Reads a generated handler with the Core parser and lists every way it leaves what it says it reserves: addresses
/// outside the CPU, V bytes outside <see cref="HandlerStats"/>' range, blocks or events it does not list, RCV/XMT on
/// the other port, special memory written beyond SMB30/130, SMB86-94/186-194 and SMB34, and every instruction the Core
/// instruction table (via <see cref="AwlProgramCheck"/> for the CPU) refuses. Operand roles (written or
/// read, widened by a count) come from the merge's <see cref="InstructionOperands"/>, so both share one reading.
/// </summary>
internal sealed class HandlerFootprintAudit
{
    /// <summary>The receive buffer behind RCV/XMT TBL: count byte plus at most 255 characters (SMB94 = 255).</summary>
    private const int BufferBytes = 256;

    private static readonly MemoryArea[] ServedAreas = [MemoryArea.I, MemoryArea.Q, MemoryArea.M, MemoryArea.V, MemoryArea.SM];

    private readonly HandlerOptions _options;
    private readonly HandlerStats _stats;
    private readonly HandlerFootprint _footprint;
    private readonly List<string> _problems = [];

    private HandlerFootprintAudit(HandlerOptions options, HandlerStats stats)
    {
        _options = options;
        _stats = stats;
        _footprint = new HandlerFootprint(options);
    }

    public SortedSet<int> VBytes { get; } = [];

    public HashSet<int> Events { get; } = [];

    /// <summary>
    /// Every problem of the handler generated for <paramref name="options"/>, each naming the line and operand;
    /// <paramref name="tamper"/> edits the text first, to prove the audit sees what it looks for.
    /// </summary>
    public static IReadOnlyList<string> Problems(HandlerOptions options, Func<string, string>? tamper = null)
    {
        var result = HandlerGenerator.Generate(options);
        if (!result.Ok)
        {
            return [.. result.Diagnostics.Select(d => $"not generated: {d.Id} {d.Message}")];
        }

        var parsed = AwlParser.Parse(tamper is null ? result.AwlText : tamper(result.AwlText));
        var audit = new HandlerFootprintAudit(options, result.Stats!);
        audit._problems.AddRange(parsed.Diagnostics.Select(d => $"parse: {d}"));
        audit._problems.AddRange(AwlProgramCheck.Check(parsed.Program, options.Cpu).Select(d => $"instruction table: {d}"));
        audit.Check(parsed.Program);
        return audit._problems;
    }

    private void Check(AwlProgram program)
    {
        var blocks = program.Blocks.Where(b => b.Kind != AwlBlockKind.OrganizationBlock)
            .Select(b => (b.Name, (b.Kind == AwlBlockKind.Subroutine ? "SBR" : "INT") + b.Number.ToString(CultureInfo.InvariantCulture)));
        Expect(blocks.SequenceEqual(_stats.Blocks.Select(b => (b.Name, b.NumberText))), $"blocks {string.Join(", ", blocks)} are not the stats' blocks");
        Expect(program.Blocks.Count(b => b.Kind == AwlBlockKind.OrganizationBlock) == 1, "not exactly one OB1");
        foreach (var instruction in program.Blocks.SelectMany(b => b.Instructions))
        {
            var uses = InstructionOperands.Uses(instruction, program).ToList();
            Expect(uses.Count == instruction.Operands.Length, $"line {instruction.Line}: an operand of {instruction.Mnemonic} does not parse");
            CheckInstruction(instruction, uses);
            uses.ForEach(use => CheckOperand(use));
        }

        Expect(Events.SetEquals(_stats.InterruptEvents), $"events {string.Join(", ", Events)} are not the stats' {string.Join(", ", _stats.InterruptEvents)}");
        // The work bytes from CommandsFirst on are kept for 07 STOP and 08 READ CHANGES: reserved, not all touched yet.
        var lastUsed = _stats.FirstVByte + HandlerLayout.CommandsFirst - 1;
        Expect(
            VBytes.Count > 0 && VBytes.Min == _stats.FirstVByte && VBytes.Max >= lastUsed && VBytes.Max <= _stats.LastVByte,
            $"V bytes touched VB{VBytes.Min}-VB{VBytes.Max}, reserved {_stats.VRange}, used at least to VB{lastUsed}");
        Expect(_stats.FirstVByte == _footprint.FirstVByte && _stats.LastVByte == _footprint.LastVByte && _stats.Port == _options.Port, "stats and merge footprint disagree");
    }

    private void CheckInstruction(AwlInstruction instruction, List<OperandUse> uses)
    {
        var at = $"line {instruction.Line}: {instruction.Mnemonic} {string.Join(", ", instruction.Operands)}";
        switch (instruction.Mnemonic)
        {
            case "RCV" or "XMT":
                Expect(IsConstant(uses[1], _options.Port), $"{at}: not on port {_options.Port}");
                // XMT through a pointer sends one of the reply's chunks: its table is a buffer byte by construction
                // (ChunkPart), which the interpreter's chunk tests check; the pointer's own bytes are checked below.
                var chunk = instruction.Mnemonic == "XMT" && uses[0].Operand.Kind == AwlOperandKind.Indirect;
                Expect(chunk || (uses[0].Operand is { Kind: AwlOperandKind.Address, Area: MemoryArea.V, Width: AccessWidth.Byte } table && table.ByteOffset == _stats.FirstVByte), $"{at}: table is not the buffer {_stats.FirstVByte}");
                TouchV(_stats.FirstVByte, _stats.FirstVByte + BufferBytes - 1, at);
                break;
            case "ATCH":
                var expected = uses[0].Operand.Text == _options.Names.Receive ? _footprint.ReceiveEvent
                    : uses[0].Operand.Text == _options.Names.Delay ? StlGen.Handler.HandlerContext.DelayEvent
                    : uses[0].Operand.Text == _options.Names.Transmit ? _footprint.TransmitEvent : -1;
                Expect(IsConstant(uses[1], expected), $"{at}: not the routine's event {expected}");
                Events.Add((int)uses[1].Operand.Integer);
                break;
            case "DTCH":
                Expect(uses[0].Operand.Kind == AwlOperandKind.Constant, $"{at}: event is not a constant");
                Events.Add((int)uses[0].Operand.Integer);
                break;
            case "CALL":
                Expect(uses.Count == 1 && uses[0].Operand.Text == _options.Names.Panel, $"{at}: not the handler's subroutine");
                break;
        }
    }

    private void CheckOperand(OperandUse use)
    {
        var operand = use.Operand;
        var at = $"line {use.Line}: {use.Instruction.Mnemonic} operand {operand.Text}";
        switch (operand.Kind)
        {
            case AwlOperandKind.Address when operand.Area == MemoryArea.AC:
                Expect(operand.ByteOffset < _options.Cpu.Accumulators, $"{at}: no such accumulator");
                break;
            case AwlOperandKind.Address:
                CheckAddress(use, at);
                break;
            case AwlOperandKind.Pointer when operand.ByteOffset == 0 && ServedAreas.Contains(operand.Area):
                // &IB0 ... &SMB0 are the protocol's area bases (HandlerSnippets.Areas): a READ or WRITE adds its OFFSET.
                Expect(_options.Cpu.TryGetArea(operand.Area, out _), $"{at}: area not on the CPU");
                break;
            case AwlOperandKind.Pointer:
                Expect(operand.Area == MemoryArea.V, $"{at}: a pointer outside V");
                TouchV(operand.ByteOffset, operand.ByteOffset, at);
                break;
            case AwlOperandKind.Indirect when operand.Area == MemoryArea.V:
                TouchV(operand.ByteOffset, operand.ByteOffset + 3, at);
                break;
            case AwlOperandKind.Indirect:
                Expect(operand.Area == MemoryArea.AC && operand.ByteOffset is >= 1 and <= 3, $"{at}: indirect through other than AC1-AC3 or a handler's VD");
                break;
            case AwlOperandKind.Local:
                _problems.Add($"{at}: the handler keeps nothing in L memory");
                break;
            case AwlOperandKind.Symbol:
                Expect(use.Index == 0 && use.Instruction.Mnemonic is "CALL" or "ATCH" && _stats.Blocks.Any(b => b.Name == operand.Text), $"{at}: not one of the handler's blocks");
                break;
        }
    }

    private void CheckAddress(OperandUse use, string at)
    {
        var operand = use.Operand;
        var access = use.Written ? AddressUse.Write : AddressUse.Read;
        var (first, last) = use.Bytes;
        if (!PlcAddress.TryParse(operand.Text, out var address, out var error))
        {
            _problems.Add($"{at}: {error.Message}");
            return;
        }

        var lastAddress = PlcAddress.ForBytes(operand.Area, last, AccessWidth.Byte);
        // What the CPU lets a program write (SMB30 and up, ...) is PPI's rule, which mirrors the CPU's own; the Freeport
        // link's (Q, M, V) is what the panel writes through the handler, not what the handler may write itself.
        var refusal = AddressRules.Check(address, _options.Cpu, access, LinkProtocol.Ppi) ?? AddressRules.Check(lastAddress, _options.Cpu, access, LinkProtocol.Ppi);
        Expect(refusal is null, $"{at}: {refusal?.Message}");

        if (operand.Area == MemoryArea.V)
        {
            TouchV(first, last, at);
        }
        else if (operand.Area == MemoryArea.SM && use.Written)
        {
            var allowed = Enumerable.Range(first, last - first + 1).All(b => b == _footprint.PortControlByte
                || b == HandlerFootprint.ReplyDelayByte || (b >= _footprint.FirstReceiveByte && b <= _footprint.LastReceiveByte));
            Expect(allowed, $"{at}: writes SMB{first}-SMB{last}, not a byte the handler reserves");
        }
    }

    private void TouchV(int first, int last, string at)
    {
        Expect(first >= _stats.FirstVByte && last <= _stats.LastVByte, $"{at}: VB{first}-VB{last} outside {_stats.VRange}");
        for (var b = first; b <= last; b++)
        {
            VBytes.Add(b);
        }
    }

    private static bool IsConstant(OperandUse use, int value) =>
        use.Operand is { Kind: AwlOperandKind.Constant, ConstantKind: AwlConstantKind.Integer } c && c.Integer == value;

    private void Expect(bool condition, string problem)
    {
        if (!condition)
        {
            _problems.Add(problem);
        }
    }
}
