using System.CommandLine;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Commands;

/// <summary><c>opanel address TEXT --cpu MODEL</c>: the canonical form of an address and what the panel may do with it.</summary>
internal static class AddressCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var text = new Argument<string>("address") { Description = "An S7-200 address such as I0.3, VB100, VW200, VD300, SMB30, AIW0" };
        var cpu = CpuOptions.Model();
        var revision = CpuOptions.Revision();
        var plcPort = new Option<int>("--plc-port") { Description = "The PLC port the handler serves, 0 or 1 (its port's SMB bytes are the handler's); default 0" };
        var command = new Command(
            "address",
            "Check an address against a CPU: canonical form, area, byte, bit, width, what the Freeport link does with it, and whether the panel may "
            + "write it (the CPU's read-only bytes, and the bytes a handler generated with the default settings keeps for itself)")
        {
            text, cpu, revision, plcPort,
        };
        command.SetAction(parse =>
        {
            var cli = context(parse);
            if (!CpuOptions.TryResolve(parse.GetValue(cpu), parse.GetValue(revision), out var profile, out var cpuError))
            {
                return cli.Fail(ExitCodes.BadInput, cpuError);
            }

            var port = parse.GetValue(plcPort);
            if (port is not (0 or 1) || port >= profile.CommunicationPorts)
            {
                return cli.Fail(ExitCodes.BadInput, $"--plc-port {port}: {profile.Name} has port{(profile.CommunicationPorts == 1 ? " 0 only" : "s 0 and 1")}");
            }

            return Describe(cli, parse.GetValue(text), profile, port);
        });
        return command;
    }

    private static int Describe(CliContext cli, string? text, CpuProfile cpu, int port)
    {
        if (!PlcAddress.TryParse(text, out var address, out var parseError))
        {
            return cli.Fail(ExitCodes.BadInput, parseError.Message);
        }

        if (AddressRules.Check(address, cpu) is { } rangeError)
        {
            return cli.Fail(ExitCodes.BadInput, rangeError.Message);
        }

        var writeError = AddressRules.Check(address, cpu, AddressUse.Write)?.Message
            ?? LinkAreas.FreeportRefusal(address)
            ?? HandlerProtection.Refusal(address, cpu, port);
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
            writeError);

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
        o.WriteLine($"link      {(ReadByLink ? $"read by the Freeport link (it reads {LinkAreas.FreeportServed})" : $"not read by the Freeport link (it reads {LinkAreas.FreeportServed})")}");
        o.WriteLine($"writable  {(Writable ? "yes" : "no: " + NotWritableBecause)}");
    }
}
