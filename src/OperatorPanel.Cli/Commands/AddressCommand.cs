using System.CommandLine;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel address TEXT --cpu MODEL</c>: the canonical form of an address and what the panel may do with it: over the
/// Freeport link (<c>writable</c>, the handler's own bytes included) and over PPI (<c>ppi</c>).
/// </summary>
internal static class AddressCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var text = new Argument<string>("address") { Description = "An S7-200 address such as I0.3, VB100, VW200, VD300, SMB30, AIW0, T37 (a timer's current value)" };
        var cpu = CpuOptions.Model();
        var revision = CpuOptions.Revision();
        var command = new Command(
            "address",
            "Check an address against a CPU: canonical form, area, byte, bit, width, what the Freeport and the PPI link do with it, and whether the "
            + "panel may write it (the CPU's read-only bytes, SM, which the Freeport handler does not serve, and the V bytes a handler generated with the default settings keeps for itself)")
        {
            text, cpu, revision,
        };
        command.SetAction(parse =>
        {
            var cli = context(parse);
            if (!CpuOptions.TryResolve(parse.GetValue(cpu), parse.GetValue(revision), out var profile, out var cpuError))
            {
                return cli.Fail(ExitCodes.BadInput, cpuError);
            }

            return Describe(cli, parse.GetValue(text), profile);
        });
        return command;
    }

    private static int Describe(CliContext cli, string? text, CpuProfile cpu)
    {
        if (!PlcAddress.TryParse(text, out var address, out var parseError))
        {
            return cli.Fail(ExitCodes.BadInput, parseError.Message);
        }

        if (AddressRules.Check(address, cpu) is { } rangeError)
        {
            return cli.Fail(ExitCodes.BadInput, rangeError.Message);
        }

        var writeError = LinkAreas.Refusal(address, LinkProtocol.Freeport, cpu, AddressUse.Write)
            ?? HandlerProtection.Refusal(address, cpu);
        var ppiWriteError = LinkAreas.Refusal(address, LinkProtocol.Ppi, cpu, AddressUse.Write);
        var view = new AddressView(
            address.ToString(),
            address.Area.ToString(),
            address.ByteOffset,
            address.Bit,
            address.Width.ToString(),
            address.Width.ByteCount(),
            address.LastByte,
            cpu.DisplayName,
            LinkAreas.Reads(LinkProtocol.Freeport, address.Area),
            writeError is null,
            writeError)
        {
            ReadByPpi = LinkAreas.Reads(LinkProtocol.Ppi, address.Area),
            WritableOverPpi = ppiWriteError is null,
            NotWritableOverPpiBecause = ppiWriteError,
        };

        if (cli.Json)
        {
            cli.WriteJson(view);
        }
        else
        {
            view.WriteText(cli.Out);
        }

        return ExitCodes.Ok;
    }
}

internal sealed record AddressView(
    string Address,
    string Area,
    int ByteOffset,
    int? Bit,
    string Width,
    int Bytes,
    int LastByte,
    string Cpu,
    bool ReadByLink,
    bool Writable,
    string? NotWritableBecause)
{
    public bool ReadByPpi { get; init; }

    public bool WritableOverPpi { get; init; }

    public string? NotWritableOverPpiBecause { get; init; }

    public void WriteText(TextWriter o)
    {
        var numbered = Area is "T" or "C";
        o.WriteLine($"address   {Address}");
        o.WriteLine($"area      {Area}");
        o.WriteLine(numbered ? $"number    {ByteOffset}" : $"byte      {ByteOffset}");
        o.WriteLine($"bit       {(Bit is { } b ? b.ToString(System.Globalization.CultureInfo.InvariantCulture) : "-")}");
        o.WriteLine(numbered ? $"width     {Width} (the current value, a signed word)" : $"width     {Width} ({Bytes} byte{(Bytes == 1 ? string.Empty : "s")}, last byte {LastByte})");
        o.WriteLine($"cpu       {Cpu}");
        o.WriteLine($"link      {(ReadByLink ? "read" : "not read")} by the Freeport link (it reads {LinkAreas.FreeportServed})");
        o.WriteLine($"writable  {(Writable ? "yes" : "no: " + NotWritableBecause)}");
        o.WriteLine($"ppi       {(ReadByPpi ? "read" : "not read")} by the PPI link (it reads {LinkAreas.PpiServed}); writable over PPI {(WritableOverPpi ? "yes" : "no: " + NotWritableOverPpiBecause)}");
    }
}
