using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Values;
using OperatorPanel.Core.Writes;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Memory;

/// <summary>Writing a cell's typed value, and changing its display format.</summary>
public sealed partial class MemoryViewModel
{
    /// <summary>
    /// Checks the typed text for the cell's type (ValueParser) and address for the station's CPU (AddressRules), then
    /// writes it; a bad value is refused with a message and nothing goes on the wire. The bus logs the write.
    /// </summary>
    internal async Task CommitAsync(MemoryCellViewModel cell)
    {
        var address = cell.PlcAddress;
        if (!cell.CanEdit)
        {
            Refuse(cell, $"{address}: {(cell.Writable ? "not connected or read-only mode" : "the project marks this cell read-only")}; nothing written");
            return;
        }

        if (!ValueParser.TryParse(cell.EditText, address, cell.Format, out var bytes, out var valueError))
        {
            Refuse(cell, valueError.Message);
            return;
        }

        if (AddressRules.Check(address, cell.Station.Cpu, AddressUse.Write) is { } addressError)
        {
            Refuse(cell, addressError.Message);
            return;
        }

        var newValue = ValueFormatter.Format(bytes.AsSpan(), address.Width, cell.Format);
        var current = cell.HasValue ? cell.ValueText : null;
        if (_options.ConfirmWrites && !await _dialogs.ConfirmAsync("Write memory", WriteMessages.Question(address, cell.Symbol, current, cell.Quality, newValue)))
        {
            return;
        }

        var request = address.Width == AccessWidth.Bit
            ? WriteRequest.Bit(cell.Station.Address, address, bytes[0] != 0)
            : WriteRequest.Bytes(cell.Station.Address, address, bytes);
        cell.EditError = null;
        cell.WriteError = null;
        cell.IsWriting = true;
        WriteOutcome outcome;
        try
        {
            outcome = await _session.WriteAsync(request);
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _logger.Error(exception, "Writing {Address} failed in the panel", address.ToString());
            outcome = new WriteOutcome.Unknown(default, $"the panel failed: {exception.Message}", "it may have reached the PLC");
        }
        finally
        {
            cell.IsWriting = false;
        }

        cell.IsEditing = false;
        cell.WriteError = WriteMessages.Problem(address, cell.Format, outcome);
        var status = WriteMessages.StatusText(cell.Symbol, address, cell.Format, newValue, outcome);
        if (cell.WriteError is null)
        {
            _session.StatusLine.Show(status);
        }
        else
        {
            _session.StatusLine.ShowError(status);
        }
    }

    /// <summary>Edits the project: the cell shows its value in <paramref name="format"/> from now on (never throws).</summary>
    internal async Task ChangeFormatAsync(MemoryCellViewModel cell, DisplayFormat format)
    {
        if (!format.Fits(cell.PlcAddress.Width))
        {
            _session.StatusLine.ShowError($"{cell.Address}: {format} does not fit a {cell.WidthText}");
            return;
        }

        var tags = cell.Station.Tags.Replace(cell.Tag, cell.Tag with { Format = format });
        try
        {
            await ApplyEditAsync(ProjectEdits.WithTags(_session.Project, cell.Station.Address, tags), (cell.Station.Address, cell.Symbol), _session.StatusLine.ShowError);
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _logger.Error(exception, "Changing the format of {Address} failed", cell.Address);
            _session.StatusLine.ShowError($"{cell.Address}: the format could not be changed: {exception.Message}");
        }
    }

    private void Refuse(MemoryCellViewModel cell, string message)
    {
        cell.EditError = message;
        _session.StatusLine.ShowError(message);
    }
}
