using System.CommandLine;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Cli.Commands;

/// <summary><c>opanel address TEXT --cpu MODEL</c>: the canonical form of an address and what the panel may do with it.</summary>
internal static class AddressCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var text = new Argument<string>("address") { Description = "An S7-200 address such as I0.3, VB100, VW200, VD300, SMB30, AIW0" };
        var cpu = CpuOptions.Model();
        var revision = CpuOptions.Revision();
        var command = new Command("address", "Check an address against a CPU: canonical form, area, byte, bit, width, and whether the panel may write it")
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

        var writeError = AddressRules.Check(address, cpu, AddressUse.Write);
        var view = new AddressView(
            address.ToString(),
            address.Area.ToString(),
            address.ByteOffset,
            address.Bit,
            address.Width.ToString(),
            address.Width.ByteCount(),
            address.LastByte,
            cpu.DisplayName,
            AddressRules.IsServedByLink(address.Area),
            writeError is null,
            writeError?.Message);

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
    public void WriteText(TextWriter o)
    {
        o.WriteLine($"address   {Address}");
        o.WriteLine($"area      {Area}");
        o.WriteLine($"byte      {ByteOffset}");
        o.WriteLine($"bit       {(Bit is { } b ? b.ToString(System.Globalization.CultureInfo.InvariantCulture) : "-")}");
        o.WriteLine($"width     {Width} ({Bytes} byte{(Bytes == 1 ? string.Empty : "s")}, last byte {LastByte})");
        o.WriteLine($"cpu       {Cpu}");
        o.WriteLine($"link      {(ReadByLink ? "read by the panel link" : "not served by the panel link (I, Q, M, V and SM are)")}");
        o.WriteLine($"writable  {(Writable ? "yes" : "no: " + NotWritableBecause)}");
    }
}
